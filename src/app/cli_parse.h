#pragma once
// Parsing of the structured option values the commands share (WxH sizes, X,Y,Z vectors), with
// one-line errors naming the option.
#include <array>
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

}  // namespace pond::app
