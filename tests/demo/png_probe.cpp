// The shell tests' look at pictures (demo, bodies, render CLI, install, package):
//   png_probe A.png B.png X Y R LEVELS   the share (0..1) of the (2R+1)^2 pixels around (X, Y)
//                                        (clipped to the picture) whose largest channel difference
//                                        exceeds LEVELS
//   png_probe share A.png B.png LEVELS   the same over the whole picture
//   png_probe size A.png                 its width and height
//   png_probe pond A.png                 whether A is a pond seen from the usual camera, right side
//                                        up: sky at the top, brighter and bluer than the land at the
//                                        bottom, and neither black nor flat; prints the numbers,
//                                        exit 1 when it is not
// Exit 2 when a file cannot be read or two pictures differ in size.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "image_compare.h"

namespace {

using pond::test::Rgba;

Rgba read(const char* path) {
  Rgba img = pond::test::read_png(path);
  if (img.width == 0) {
    std::fprintf(stderr, "png_probe: %s is not a readable PNG\n", path);
    std::exit(2);
  }
  return img;
}

double share(const Rgba& a, const Rgba& b, int x0, int y0, int x1, int y1, int levels) {
  if (a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "png_probe: the pictures differ in size (%dx%d, %dx%d)\n", a.width, a.height, b.width, b.height);
    std::exit(2);
  }
  int total = 0, differing = 0;
  for (int py = std::max(0, y0); py <= std::min(a.height - 1, y1); ++py)
    for (int px = std::max(0, x0); px <= std::min(a.width - 1, x1); ++px) {
      const std::size_t k = (static_cast<std::size_t>(py) * a.width + px) * 4;
      int most = 0;
      for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(a.pixels[k + c] - b.pixels[k + c]));
      ++total;
      differing += most > levels;
    }
  return total ? static_cast<double>(differing) / total : 0.0;
}

struct Band {
  double r = 0, g = 0, b = 0;
  double brightness() const { return (r + g + b) / 3; }
};

// The mean colour of rows [y0, y1).
Band band(const Rgba& img, int y0, int y1) {
  Band m;
  const double n = static_cast<double>(y1 - y0) * img.width;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = &img.pixels[(static_cast<std::size_t>(y) * img.width + x) * 4];
      m.r += p[0] / n, m.g += p[1] / n, m.b += p[2] / n;
    }
  return m;
}

// The default camera looks over the pond from its shore: a strip of pale sky at the top, the water
// in the middle, the grass of the near shore at the bottom. Upside down, the grass is at the top;
// black or a flat fill has no such contrast.
int check_pond(const Rgba& img) {
  const int strip = std::max(1, img.height / 25);
  const Band top = band(img, 0, strip), bottom = band(img, img.height - strip, img.height);
  const Band middle = band(img, img.height / 3, 2 * img.height / 3);
  std::printf("top (%.0f, %.0f, %.0f), middle (%.0f, %.0f, %.0f), bottom (%.0f, %.0f, %.0f)\n", top.r, top.g, top.b,
              middle.r, middle.g, middle.b, bottom.r, bottom.g, bottom.b);
  int problems = 0;
  auto problem = [&](const char* what) {
    std::printf("png_probe: %s\n", what);
    ++problems;
  };
  if (!(top.brightness() > bottom.brightness() + 40)) problem("the top is not brighter than the bottom: no sky above the shore");
  if (!(top.b > top.r + 10)) problem("the top is not sky blue");
  if (!(bottom.g > bottom.b)) problem("the bottom is not the green shore");
  if (!(middle.b > middle.r + 10)) problem("the middle is not the blue-green water");
  if (!(middle.brightness() > 30)) problem("the picture is (nearly) black");
  return problems ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 7) {
    const Rgba a = read(argv[1]), b = read(argv[2]);
    const int x = std::atoi(argv[3]), y = std::atoi(argv[4]), r = std::atoi(argv[5]), levels = std::atoi(argv[6]);
    std::printf("%.6f\n", share(a, b, x - r, y - r, x + r, y + r, levels));
    return 0;
  }
  if (argc == 5 && std::strcmp(argv[1], "share") == 0) {
    const Rgba a = read(argv[2]), b = read(argv[3]);
    std::printf("%.6f\n", share(a, b, 0, 0, a.width - 1, a.height - 1, std::atoi(argv[4])));
    return 0;
  }
  if (argc == 3 && std::strcmp(argv[1], "size") == 0) {
    const Rgba a = read(argv[2]);
    std::printf("%d %d\n", a.width, a.height);
    return 0;
  }
  if (argc == 3 && std::strcmp(argv[1], "pond") == 0) return check_pond(read(argv[2]));
  std::fprintf(stderr,
               "usage: png_probe A.png B.png X Y R LEVELS | share A.png B.png LEVELS | size A.png | pond A.png\n");
  return 2;
}
