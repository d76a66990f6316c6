#pragma once
// The fuzz targets: each takes one input's bytes and returns 0. Bad input must end in the contract's
// InputError (exit 2 with a message); anything else that escapes (another exception, a crash, UB
// under the sanitizers, a failed property check) is a bug. Built two ways: as libFuzzer programs
// (libfuzzer_entry.cpp, POND_FUZZ=ON with clang) and as a GoogleTest that replays the committed
// corpora and regression inputs in every build (replay_test.cpp).
#include <cstddef>
#include <cstdint>

namespace pond::fuzz {

int scene(const std::uint8_t* data, std::size_t size);  // parse_scene, then build_model + 2 steps
int npy(const std::uint8_t* data, std::size_t size);    // npy_decode, then an encode round trip
int cli(const std::uint8_t* data, std::size_t size);    // argv (one argument per line), parse only
int checkpoint(const std::uint8_t* data, std::size_t size);  // decode_checkpoint, then resume and step

// Fails loudly (abort) with a message: what the fuzzer and the replay test both catch.
[[noreturn]] void property_failed(const char* what);

}  // namespace pond::fuzz
