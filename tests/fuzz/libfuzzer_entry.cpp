// The libFuzzer entry point of one target, chosen at compile time (POND_FUZZ_TARGET=scene|npy|cli).
#include "targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pond::fuzz::POND_FUZZ_TARGET(data, size);
}
