#pragma once
// Image comparison for the golden tests: the share of pixels whose largest channel difference
// exceeds a few levels (a tolerance that survives rasterizer rounding, not a changed picture), and
// a diff image (differing pixels red over a dimmed copy of the expected image) for failures.
#include <cstdint>
#include <string>
#include <vector>

namespace pond::test {

struct Rgba {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // RGBA8, top row first
};

Rgba read_png(const std::string& path);  // empty (width 0) when missing or unreadable

struct ImageDiff {
  double share = 1.0;   // share of pixels differing by more than `levels` in some channel
  int max_difference = 255;
  Rgba diff;            // red where they differ
};

ImageDiff compare(const Rgba& expected, const Rgba& actual, int levels);

// The luminance of pixel (x, y) in linear light (its sRGB channels decoded; Rec. 709 weights).
double linear_luminance(const Rgba& image, int x, int y);

}  // namespace pond::test
