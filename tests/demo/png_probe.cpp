// The demo tests' look at two screenshots: how many pixels of a square around (x, y) differ.
//   png_probe A.png B.png X Y R LEVELS
// prints the share (0..1) of the (2R+1)^2 pixels around (X, Y) (clipped to the picture) whose
// largest channel difference exceeds LEVELS; exit 2 when a file cannot be read or the sizes differ.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "image_compare.h"

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: png_probe A.png B.png X Y R LEVELS\n");
    return 2;
  }
  const pond::test::Rgba a = pond::test::read_png(argv[1]), b = pond::test::read_png(argv[2]);
  if (a.width == 0 || a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "png_probe: %s and %s are not two readable pictures of one size\n", argv[1], argv[2]);
    return 2;
  }
  const int x = std::atoi(argv[3]), y = std::atoi(argv[4]), r = std::atoi(argv[5]), levels = std::atoi(argv[6]);
  int total = 0, differing = 0;
  for (int py = std::max(0, y - r); py <= std::min(a.height - 1, y + r); ++py)
    for (int px = std::max(0, x - r); px <= std::min(a.width - 1, x + r); ++px) {
      const std::size_t k = (static_cast<std::size_t>(py) * a.width + px) * 4;
      int most = 0;
      for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(a.pixels[k + c] - b.pixels[k + c]));
      ++total;
      differing += most > levels;
    }
  std::printf("%.4f\n", total ? static_cast<double>(differing) / total : 0.0);
  return 0;
}
