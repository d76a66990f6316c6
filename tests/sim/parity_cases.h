#pragma once
// The parity suite's scenes (tests/gpu/test_parity.cpp: GPU exact == CPU scalar exact), also run
// without a GPU by parity_hashes (tests/sim/parity_hashes.cpp) to compare the CPU backends' state
// hashes across machines: x86-64 scalar against aarch64 scalar and neon (scripts/test.sh).
#include <cstdint>

namespace pond::test {

struct ParityCase {
  const char* name;
  const char* json;
  std::int64_t steps;
};

// Perturbation snippets: every kind, at several steps.
// (R, C): the main splash; (R2, C2): a second point, fractional, where two perturbations overlap
// at one step (their order matters).
#define POND_SPLASHES(R, C, R2, C2)                                                                           \
  "{\"step\": 0, \"row\": " #R ", \"col\": " #C ", \"radius\": 1.5, \"amplitude\": 0.8, \"target\": \"velocity\", \"mode\": \"add\"}," \
  "{\"step\": 7, \"row\": " #R2 ", \"col\": " #C2 ", \"radius\": 1.0, \"amplitude\": -0.3, \"target\": \"position\", \"mode\": \"add\"}," \
  "{\"step\": 7, \"row\": " #R ", \"col\": " #C ", \"radius\": 1.0, \"amplitude\": 0.2, \"target\": \"position\", \"mode\": \"set\"}," \
  "{\"step\": 2500, \"row\": " #R ", \"col\": " #C ", \"radius\": 2.0, \"amplitude\": 0.5, \"target\": \"velocity\", \"mode\": \"set\"}," \
  "{\"step\": 6000, \"row\": 0.5, \"col\": 0.5, \"radius\": 3.0, \"amplitude\": 0.4, \"target\": \"position\", \"mode\": \"add\"}"

inline const ParityCase kCases[] = {
    {"paper_50x50_default", "", 10000},
    {"rect_41x67_vertical_border_islands",
     R"({"grid": {"rows": 41, "cols": 67, "spacing": 0.5},
         "physics": {"mass": 4.0, "stiffness": 7.0, "damping": 0.05, "dt": 0.4},
         "border": "vertical",
         "constraints": [{"kind": "fixed", "rows": [10, 14], "cols": [20, 25]},
                         {"kind": "fixed", "rows": [30, 30], "cols": [50, 52]},
                         {"kind": "vertical", "rows": [5, 35], "cols": [40, 41]}],
         "perturbations": [)" POND_SPLASHES(20, 33, 21.5, 33.25) R"(]})",
     10000},
    {"tiny_2x2_free",
     R"({"grid": {"rows": 2, "cols": 2}, "border": "free",
         "perturbations": [)" POND_SPLASHES(0.5, 0.5, 1, 0.25) R"(]})",
     10000},
    {"strip_3x97_free_substeps",
     R"({"grid": {"rows": 3, "cols": 97}, "border": "free",
         "physics": {"mass": 4.0, "stiffness": 7.0, "damping": 0.05, "dt": 0.4, "substeps": 3},
         "perturbations": [)" POND_SPLASHES(1, 48, 1.5, 48.75) R"(]})",
     10000},
    {"all_vertical_64x48_pretension",
     R"({"grid": {"rows": 64, "cols": 48}, "border": "vertical",
         "physics": {"mass": 4.0, "stiffness": 7.0, "damping": 0.02, "dt": 0.3, "rest_ratio": 0.9},
         "constraints": [{"kind": "vertical", "rows": [0, 63], "cols": [0, 47]}],
         "perturbations": [)" POND_SPLASHES(31, 24, 30.5, 25) R"(]})",
     10000},
    {"big_splash_17x33_fixed",
     R"({"grid": {"rows": 17, "cols": 33}, "border": "fixed",
         "physics": {"mass": 4.0, "stiffness": 7.0, "damping": 0.05, "dt": 0.4, "substeps": 2},
         "perturbations": [{"step": 3, "row": 8, "col": 16, "radius": 2.0, "amplitude": 6.0,
                            "target": "position", "mode": "add"},
                           {"step": 3, "row": 8.5, "col": 15, "radius": 1.0, "amplitude": 2.0,
                            "target": "velocity", "mode": "set"}]})",
     10000},
    {"wide_24x200_quad_islands",
     R"({"grid": {"rows": 24, "cols": 200}, "border": "free",
         "constraints": [{"kind": "fixed", "rows": [8, 12], "cols": [90, 97]},
                         {"kind": "vertical", "rows": [0, 23], "cols": [180, 199]}],
         "perturbations": [)" POND_SPLASHES(12, 40, 11.5, 150) R"(]})",
     10000},
    {"square_301x301_islands",
     R"({"grid": {"rows": 301, "cols": 301}, "border": "fixed",
         "constraints": [{"kind": "fixed", "rows": [100, 120], "cols": [200, 230]},
                         {"kind": "vertical", "rows": [250, 260], "cols": [10, 290]}],
         "perturbations": [{"step": 0, "row": 150, "col": 150, "radius": 4.0, "amplitude": 1.0,
                            "target": "velocity", "mode": "add"},
                           {"step": 400, "row": 60.5, "col": 240.25, "radius": 3.0, "amplitude": 0.7,
                            "target": "position", "mode": "set"}]})",
     1500},
    {"square_257x257_demo_size",  // the demo's grid: 3 padding columns, a splash at the right border
     R"({"grid": {"rows": 257, "cols": 257}, "border": "free",
         "constraints": [{"kind": "fixed", "rows": [60, 80], "cols": [240, 256]}],
         "perturbations": [{"step": 0, "row": 128, "col": 255.5, "radius": 3.0, "amplitude": 1.0,
                            "target": "velocity", "mode": "add"},
                           {"step": 300, "row": 200, "col": 256, "radius": 2.0, "amplitude": 0.5,
                            "target": "position", "mode": "set"}]})",
     1000},
    {"tiny_6x4_free",  // one group of 4 columns, both borders in it, no padding
     R"({"grid": {"rows": 6, "cols": 4}, "border": "free",
         "perturbations": [)" POND_SPLASHES(2, 3, 3.5, 0.5) R"(]})",
     10000},
    {"tiny_5x5_vertical",  // the last group: one real column (no right neighbour) and 3 padding
     R"({"grid": {"rows": 5, "cols": 5}, "border": "vertical",
         "physics": {"mass": 4.0, "stiffness": 7.0, "damping": 0.05, "dt": 0.4, "substeps": 2},
         "perturbations": [)" POND_SPLASHES(2, 4, 1.5, 3.75) R"(]})",
     10000},
    {"bodies_41x67_mixed_islands",  // bodies: a width that is not a multiple of 4, substeps, a kernel
                                    // wider than the 8 lanes
     R"({"grid": {"rows": 41, "cols": 67}, "physics": {"substeps": 2, "gravity": 0.05},
         "basin": {"floor_depth": 6.0},
         "constraints": [{"kind": "fixed", "rows": [24, 27], "cols": [33, 38]}],
         "perturbations": [{"step": 5, "row": 13, "col": 22, "radius": 2.0, "amplitude": 1.0}],
         "bodies": [{"motion": "kinematic", "radius": 3.0,
                     "path": [[0, 6, 0.5, 20], [120, 60, 0.5, 20], [160, 60, -1, 12]]},
                    {"motion": "floating", "radius": 2.0, "mass": 30, "position": [16, 3, 10],
                     "velocity": [0, -0.3, 0]},
                    {"motion": "floating", "radius": 2.5, "mass": 20, "position": [47, 2, 30],
                     "velocity": [0.05, 0, -0.02]},
                    {"motion": "floating", "radius": 4.6, "density": 0.5, "position": [30.3, 1, 11.6],
                     "velocity": [0.1, 0, 0.05]}]})",
     3000},
    {"bodies_48x64_colliding",  // bodies: a multiple of 4; floating balls that collide, one into the rim
     R"({"grid": {"rows": 48, "cols": 64, "spacing": 0.5}, "border": "vertical",
         "physics": {"rest_ratio": 0.9, "damping": 0.1, "gravity": 0.2},
         "basin": {"floor_depth": 2.0, "land_height": 0.5},
         "bodies": [{"motion": "floating", "radius": 2.0, "density": 0.3, "position": [10, 1.5, 12]},
                    {"motion": "floating", "radius": 1.5, "density": 0.6, "position": [15.5, 2.5, 12.5],
                     "velocity": [-0.6, 0, 0.1]},
                    {"motion": "floating", "radius": 1.0, "density": 0.5, "position": [24, 1, 20],
                     "velocity": [2.0, 0, 0]},
                    {"motion": "floating", "radius": 1.0, "density": 1.5, "position": [20, 1, 6],
                     "velocity": [0.3, -1.0, 0.2]},
                    {"motion": "kinematic", "radius": 1.5, "path": [[10, 5, -0.5, 5], [400, 25, 0.2, 20]]}]})",
     3000},
    {"bodies_65x65_sunk_and_dropped",  // a stone resting on the floor, one dropped in, one sinking
                                       // from under the surface: the floor's contact after the drag
     R"({"grid": {"rows": 65, "cols": 65}, "basin": {"floor_depth": 5.0},
         "bodies": [{"motion": "floating", "radius": 1.5, "density": 2, "position": [32, -3.5, 32]},
                    {"motion": "floating", "radius": 2.0, "density": 3, "position": [15, 3, 48]},
                    {"motion": "floating", "radius": 1.5, "density": 1.2, "position": [48, -1.8, 16]}]})",
     5000},
    {"narrow_7x6_free",  // the last group: two real columns and 2 padding
     R"({"grid": {"rows": 7, "cols": 6}, "border": "free",
         "perturbations": [)" POND_SPLASHES(3, 5, 4.5, 4.25) R"(]})",
     10000},
};

}  // namespace pond::test
