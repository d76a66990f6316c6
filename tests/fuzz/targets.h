#pragma once
// The fuzz targets: each takes one input's bytes and returns 0. Bad input must end in the contract's
// InputError (exit 2 with a message); anything else that escapes (another exception, a crash, UB
// under the sanitizers, a broken property: what the code under test must keep for every input,
// checked by the target) is a bug. Built two ways: as libFuzzer programs
// (libfuzzer_entry.cpp, POND_FUZZ=ON with clang) and as a GoogleTest that replays the committed
// corpora and regression inputs in every build (replay_test.cpp).
#include <cstddef>
#include <cstdint>

namespace pond::fuzz {

int scene(const std::uint8_t* data, std::size_t size);  // parse_scene, build_model, 3 steps, the spec's rules
int npy(const std::uint8_t* data, std::size_t size);    // npy_decode, then an encode round trip
int cli(const std::uint8_t* data, std::size_t size);    // argv (one argument per line), parse only
int checkpoint(const std::uint8_t* data, std::size_t size);  // decode_checkpoint, then resume and step

// A broken property. By default it prints `what` and aborts (libFuzzer keeps the input as a crash);
// the replay test installs a handler that throws, so an input that breaks a property fails its
// test with the property named, like any other failed expectation.
using PropertyHandler = void (*)(const char* what);
void set_property_handler(PropertyHandler handler);  // nullptr: abort
[[noreturn]] void property_failed(const char* what);

}  // namespace pond::fuzz
