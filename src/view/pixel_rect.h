#pragma once
// A rectangle of a view's pixels: where the sun's shadows can show (view/sun_shadow.h), what a
// scissored draw needs of a mesh (view/triangle_cull.h).

#include <algorithm>
#include <cmath>
#include <optional>

namespace pond::view {

// A rectangle of pixels (x0, y0 inclusive; x1, y1 exclusive). In a frame's plan, what it is for:
// a shadow can fall there, what is under the water can show there (view/frame_plan.h).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool shadowed = false, submerged = false;
};

// The pixels of a width x height view covering the extent [x0, x1] x [y0, y1] (pixel coordinates)
// with two pixels of margin (a filter's reach, rounding), clamped to the view; nothing when that
// is empty. (Clamped as doubles: a point just in front of the eye can land far outside any int.)
inline std::optional<PixelRect> padded_pixels(double x0, double y0, double x1, double y1, int width, int height) {
  auto pixel = [](double v, int size) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(size))); };
  const PixelRect rect{pixel(std::floor(x0) - 2.0, width), pixel(std::floor(y0) - 2.0, height),
                       pixel(std::ceil(x1) + 2.0, width), pixel(std::ceil(y1) + 2.0, height)};
  if (rect.x0 >= rect.x1 || rect.y0 >= rect.y1) return std::nullopt;
  return rect;
}

}  // namespace pond::view
