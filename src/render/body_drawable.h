#pragma once
// The bodies in the water (issue 16) in the frame loop's pass (render/frame_loop.h PassDrawable):
// lit spheres, one instance of a unit icosphere (render/sphere_mesh.h, built once at four levels
// of detail) per body, each at the coarsest level whose outline is within half a pixel of the
// sphere's at its size on screen.
//
// Per frame, prepare() writes each body's radius and colour (Session::water().bodies) into the
// slot's host-visible instance buffer (flushed: it need not be coherent) and picks its level of
// detail from the host's copy of its state (Session::bodies(), the same values as drawn); draw()
// draws every instance at its centre read from the bodies' states on the GPU (FrameInfo::bodies:
// the GPU solver's own buffer), so nothing waits for the bodies to come back to draw them. Kinematic bodies are brick red, floating ones buoy
// yellow; a body the demo holds (Session::held) is drawn lighter. A body's part under the water is
// depth-tested against the surface like everything else, and drawn again into the submerged layer
// (render/submerged_pass.h), through which clear water shows it refracted.
#include <cstddef>
#include <memory>

#include "render/frame_loop.h"
#include "render/pass_drawable.h"

namespace pond::render {

class BodyDrawable final : public PassDrawable {
 public:
  // Uses the loop's colour format and session (which must outlive the drawable).
  BodyDrawable(const gpu::Context& ctx, const FrameLoop& loop);
  ~BodyDrawable() override;
  BodyDrawable(const BodyDrawable&) = delete;
  BodyDrawable& operator=(const BodyDrawable&) = delete;

  void prepare(const FrameInfo& frame) override;
  void draw(const FrameInfo& frame) override;
  void draw_reflected(const FrameInfo& frame) override;  // the part above the water, mirrored
  void draw_submerged(const FrameInfo& frame) override;  // the part below it
  // Each body's sphere; drawn into the sun's shadow map (at the frame's level of detail).
  void add_shadow_casters(std::vector<view::ShadowCaster>& casters) const override;
  void draw_shadow(const FrameInfo& frame) override;

  std::size_t drawn() const;      // bodies in the last prepared frame
  std::size_t triangles() const;  // their triangles (each at its level of detail)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pond::render
