#pragma once
// Reading a rendered picture at a world point: where the point projects, how bright the pixel is.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "golden.h"
#include "image_compare.h"

namespace pond::test {

// The pixel a world point projects to on a width x height picture (by default the image tests'
// size; view_proj: column-major, Vulkan clip space, y down), or {-1, -1} behind the camera.
inline std::array<int, 2> project_to_pixel(const std::array<float, 16>& m, double x, double y, double z,
                                           int width = kWidth, int height = kHeight) {
  const double cx = m[0] * x + m[4] * y + m[8] * z + m[12], cy = m[1] * x + m[5] * y + m[9] * z + m[13];
  const double cw = m[3] * x + m[7] * y + m[11] * z + m[15];
  if (cw <= 0) return {-1, -1};
  return {static_cast<int>(std::floor((cx / cw * 0.5 + 0.5) * width)),
          static_cast<int>(std::floor((cy / cw * 0.5 + 0.5) * height))};
}

// Luminance-ish brightness of a pixel (sum of the encoded channels, 0..765).
inline int pixel_brightness(const Rgba& img, int x, int y) {
  const std::uint8_t* p = &img.pixels[(static_cast<std::size_t>(y) * img.width + x) * 4];
  return p[0] + p[1] + p[2];
}

}  // namespace pond::test
