#include "image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

namespace pond::test {

Rgba read_png(const std::string& path) {
  Rgba img;
  int channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &img.width, &img.height, &channels, 4);
  if (!data) return Rgba{};
  img.pixels.assign(data, data + static_cast<std::size_t>(img.width) * img.height * 4);
  stbi_image_free(data);
  return img;
}

ImageDiff compare(const Rgba& expected, const Rgba& actual, int levels) {
  ImageDiff d;
  if (expected.width != actual.width || expected.height != actual.height) return d;
  d.diff = expected;
  d.max_difference = 0;
  std::size_t differing = 0;
  const std::size_t pixels = static_cast<std::size_t>(expected.width) * expected.height;
  for (std::size_t p = 0; p < pixels; ++p) {
    int m = 0;
    for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(expected.pixels[4 * p + c] - actual.pixels[4 * p + c]));
    d.max_difference = std::max(d.max_difference, m);
    std::uint8_t* out = &d.diff.pixels[4 * p];
    if (m > levels) {
      ++differing;
      out[0] = 255, out[1] = 0, out[2] = 0;
    } else {
      for (int c = 0; c < 3; ++c) out[c] = static_cast<std::uint8_t>(out[c] / 3);
    }
    out[3] = 255;
  }
  d.share = pixels ? static_cast<double>(differing) / static_cast<double>(pixels) : 1.0;
  return d;
}

double linear_luminance(const Rgba& image, int x, int y) {
  const std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                             static_cast<std::size_t>(x))];
  const auto linear = [](std::uint8_t c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(p[0]) + 0.7152 * linear(p[1]) + 0.0722 * linear(p[2]);
}

}  // namespace pond::test
