#pragma once
// The one family of failures pond reports, and so its exit codes (`main` catches them once and
// prints the one-line message):
//  - InputError (exit 2): what the user gave is wrong (a file, a flag, a parameter, a scene value);
//  - RuntimeError (exit 1): the machine failed while running (no Vulkan device, a full disk);
//    GpuFailure is the GPU's kind of it (a lost device, memory it cannot allocate), which a
//    simulation session survives by going on on the CPU (sim/session.h);
//  - InternalError (exit 1, "internal error: ..."): pond broke one of its own invariants (a caller
//    passed what its callee's contract rules out). Never the user's fault.
#include <stdexcept>
#include <string>

namespace pond {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct InputError : Error {
  using Error::Error;
};

struct RuntimeError : Error {
  using Error::Error;
};

struct GpuFailure : RuntimeError {
  enum class Kind { device_lost, out_of_memory };
  GpuFailure(Kind k, const std::string& what) : RuntimeError(what), kind(k) {}
  Kind kind;
};

struct InternalError : Error {
  using Error::Error;
};

}  // namespace pond
