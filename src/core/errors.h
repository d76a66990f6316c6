#pragma once
// The two kinds of failure pond reports, and so its exit codes: bad input from the user (a file, a
// flag, a parameter) is an InputError and exits 2; a failure while running (no Vulkan device, a disk
// that fills up) is a RuntimeError and exits 1. Both carry a one-line message that names what is
// wrong; `main` prints it and nothing else.
#include <stdexcept>
#include <string>

namespace pond {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RuntimeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace pond
