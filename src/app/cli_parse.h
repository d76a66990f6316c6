#pragma once
// Parsing of the option values the commands share (numbers, WxH sizes, X,Y,Z vectors), with
// one-line errors naming the option and quoting what was typed (core/text.h).
#include <CLI/CLI.hpp>
#include <array>
#include <cstdint>
#include <string>

#include "sim/solver.h"

namespace pond::app {

struct Size2 {
  int width = 0, height = 0;
};

Size2 parse_size(const std::string& text, const char* option);                 // "1280x720"
std::array<double, 3> parse_vec3(const std::string& text, const char* option);  // "1,2.5,-3"
// --solver's value: "gpu", "auto" (the widest backend this CPU has) or a CPU backend's name (the
// CLI11 option has checked it is one). Whether the CPU has that backend is the solver's check.
sim::SolverChoice parse_solver(const std::string& name, sim::MathMode math = sim::MathMode::exact, int threads = 0);

// Checks for numeric options, in pond's words ("--steps: must be a whole number from 0 to
// 1099511627776 in decimal digits, not '1e3'"). Each rewrites the value in plain decimal, so CLI11's
// own conversion (which reads "010" as octal) gets what was checked: add them with ->transform.
// An integer in decimal digits (a leading minus allowed) within [lo, hi].
CLI::Validator whole_number(std::int64_t lo, std::int64_t hi);
// A finite number within [lo, hi] (nan and inf refused); `what` says what is allowed, e.g.
// "a number of pixels >= 0 (0 = the full mesh), at most 1e6".
CLI::Validator real_number(double lo, double hi, std::string what);
inline constexpr const char* kFovyRange = "a number of degrees from 0.01 to 179.99";  // --fovy of render and lod

}  // namespace pond::app
