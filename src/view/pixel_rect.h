#pragma once
// A rectangle of a view's pixels: where the sun's shadows can show (view/sun_shadow.h), what a
// scissored draw needs of a mesh (view/triangle_cull.h).

namespace pond::view {

// A rectangle of pixels (x0, y0 inclusive; x1, y1 exclusive). In a frame's plan, what it is for:
// a shadow can fall there, what is under the water can show there (view/frame_plan.h).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool shadowed = false, submerged = false;
};

}  // namespace pond::view
