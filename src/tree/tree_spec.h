#pragma once
// The wind trees and the wind of a scene file ("tree", "wind"), as src/scene validates them.
#include <array>
#include <cstdint>
#include <vector>

namespace pond::tree {

// "tree": wind trees (SPEC section 2) standing on the land; absent = no tree. One skeleton, drawn
// once per position (instances), each instance swaying with its own phase.
enum class TreeBend { article, keep_length };  // the article's stretching bend | length-preserving
enum class TreeDraw { lines, tubes };          // the article's line look | lit, tapered tubes
struct TreeSpec {
  int depth = 8;                  // recursion levels 1..10 (3281 vertices at 8)
  std::uint64_t seed = 1;         // the skeleton's and the twig jitter's random streams
  double height = 6.0;            // world units from the base to the highest rest vertex
  // [row, col] grid indices (fractional allowed) of each instance's base; its foot is at
  // basin.land_height. Default: the centre of the first fixed constraint (the island).
  std::vector<std::array<double, 2>> positions;
  TreeBend bend = TreeBend::article;
  TreeDraw draw = TreeDraw::tubes;
  bool leaves = true;             // small leaves at the thinnest twigs' tips
  bool operator==(const TreeSpec&) const = default;
};

// "wind": the user wind W the trees bend in (the demo's keys 1-9 and right drag); meaningful
// without a tree too when it ripples the water.
struct WindSpec {
  double strength = 3.0;       // 0 (calm) .. 9 (gale)
  double direction_deg = 0.0;  // in the xz plane, from +x toward +z (world)
  std::uint64_t seed = 1;      // the gust noise table
  bool ripples = false;        // gusts also drop small deterministic ripples on the water
  bool operator==(const WindSpec&) const = default;
};

}  // namespace pond::tree
