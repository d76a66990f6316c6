#include "app/check_cases.h"

namespace pond::app {
namespace {

const CheckCase kCases[] = {
    {"paper_pond", "", 2000, "the paper's 50 x 50 pond, island and splash (the golden hash's scene)"},
    {"vertical_border_islands",
     R"({"grid": {"rows": 41, "cols": 67, "spacing": 0.5}, "border": "vertical",
         "constraints": [{"kind": "fixed", "rows": [10, 14], "cols": [20, 25]},
                         {"kind": "fixed", "rows": [30, 30], "cols": [50, 52]},
                         {"kind": "vertical", "rows": [5, 35], "cols": [40, 41]}],
         "perturbations": [{"step": 0, "row": 20, "col": 33, "radius": 1.5, "amplitude": 0.8}]})",
     3000, "a vertical-only border, islands and a vertical strip"},
    // Pre-tensioned (rest_ratio < 1: small waves are linear) and damped hard, every mode decays as
    // exp(-0.125 t): after ~1700 steps many of the state's values are denormals on their way to zero,
    // where a flushing device first differs.
    {"denormal_decay",
     R"({"grid": {"rows": 16, "cols": 16}, "physics": {"damping": 1.0, "rest_ratio": 0.8},
         "perturbations": [{"step": 0, "row": 7.5, "col": 7.5, "radius": 2.0, "amplitude": 1.0}]})",
     2500, "waves that decay through the denormal range"},
    {"every_perturbation_kind",
     R"({"grid": {"rows": 24, "cols": 30}, "border": "free",
         "perturbations": [
           {"step": 0, "row": 12, "col": 15, "radius": 1.5, "amplitude": 0.8, "target": "velocity", "mode": "add"},
           {"step": 7, "row": 10.5, "col": 20.25, "radius": 1.0, "amplitude": -0.3, "target": "position", "mode": "add"},
           {"step": 7, "row": 12, "col": 15, "radius": 1.0, "amplitude": 0.2, "target": "position", "mode": "set"},
           {"step": 900, "row": 5, "col": 5, "radius": 2.0, "amplitude": 0.5, "target": "velocity", "mode": "set"}]})",
     2000, "velocity and position, add and set, two at one step"},
    {"odd_width_17x33",
     R"({"grid": {"rows": 17, "cols": 33}, "physics": {"substeps": 2},
         "perturbations": [{"step": 3, "row": 8, "col": 32, "radius": 2.0, "amplitude": 2.0, "target": "position"}]})",
     2000, "a width that is not a multiple of 4 (padded rows), a splash at the right border, substeps"},
    {"bodies",
     R"({"grid": {"rows": 33, "cols": 45}, "physics": {"rest_ratio": 0.95, "gravity": 0.05},
         "constraints": [{"kind": "fixed", "rows": [20, 23], "cols": [30, 34]}],
         "bodies": [{"motion": "kinematic", "radius": 3.0, "path": [[0, 5, 0.5, 10], [150, 40, 0.5, 10]]},
                    {"motion": "floating", "radius": 2.0, "mass": 30, "position": [12, 3, 22], "velocity": [0, -0.2, 0]},
                    {"motion": "floating", "radius": 2.5, "mass": 20, "position": [19, 1, 25]}]})",
     1500, "a dragged sphere and two floating balls (the contact pass and its reductions)"},
    {"floating",
     R"({"grid": {"rows": 41, "cols": 57}, "physics": {"substeps": 2},
         "constraints": [{"kind": "fixed", "rows": [18, 23], "cols": [26, 31]}],
         "perturbations": [{"step": 20, "row": 10, "col": 10, "radius": 2.5, "amplitude": 1.5}],
         "bodies": [{"motion": "floating", "radius": 2.0, "density": 0.5, "position": [8, 0, 30], "velocity": [0.8, 0, 0]},
                    {"motion": "floating", "radius": 2.5, "density": 0.7, "position": [44, 0, 31], "velocity": [-0.8, 0, 0]},
                    {"motion": "floating", "radius": 1.5, "density": 0.3, "position": [28, 4, 20]},
                    {"motion": "floating", "radius": 1.5, "density": 2.0, "position": [14, 2, 10], "velocity": [0, -2, 0]},
                    {"motion": "floating", "radius": 2.0, "density": 0.4, "position": [50, 0, 4], "velocity": [1, 0, -1]}]})",
     1500, "floating balls: two collide head-on, one drops onto an island, one sinks, one runs into a corner"},
};

}  // namespace

std::span<const CheckCase> check_cases() { return kCases; }

scene::Scene check_scene(const CheckCase& c) {
  return *c.json ? scene::parse_scene(c.json, c.name) : scene::load_scene("");
}

}  // namespace pond::app
