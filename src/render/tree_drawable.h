#pragma once
// The wind tree in the frame loop's pass (render/frame_loop.h PassDrawable): the scene's "tree" grown
// once (src/tree), drawn at every position of the scene (instances, each with its own wind phase),
// bending in the scene's "wind".
//
// Per frame, prepare() takes each instance's wind from the session (sim::Session::wind(): gusts and
// inertia, tree/wind.h; the front end moves its clock), writes the slot's camera/light uniforms,
// and picks each instance's level of detail (tubes for the levels wide enough on screen, twig lines
// for the thinner ones, one triangle a leaf when the leaves are a few pixels long: tree/tree_lod.h);
// draw() pushes each instance's TreeWindFrame and draws lines, or tubes and twig lines (+ leaves).
//
// Controls (the demo's double-click, ImGui fields) may be called between frames; regrow() waits for
// the device, the rest only change what the next frame uses. The wind's controls are the session's.
#include <cstdint>
#include <memory>
#include <vector>

#include "render/frame_loop.h"
#include "scene/scene.h"
#include "tree/tree.h"
#include "tree/wind_state.h"
#include "render/pass_drawable.h"

namespace pond::render {

struct TreeDrawStats {
  std::size_t instances = 0, skeleton_vertices = 0, mesh_vertices = 0;
  std::size_t line_segments = 0, tube_triangles = 0, leaf_triangles = 0;
};

class TreeDrawable final : public PassDrawable {
 public:
  // Uses the loop's colour format, scene (land height), model (grid spacing) and session (the wind)
  // and the given tree (usually loop.scene().tree).
  TreeDrawable(const gpu::Context& ctx, const FrameLoop& loop, const tree::TreeSpec& tree);
  ~TreeDrawable() override;
  TreeDrawable(const TreeDrawable&) = delete;
  TreeDrawable& operator=(const TreeDrawable&) = delete;

  void prepare(const FrameInfo& frame) override;
  void draw(const FrameInfo& frame) override;
  void draw_reflected(const FrameInfo& frame) override;  // mirrored, into the planar reflection
  // Each instance's bent bounding sphere; drawn into the sun's shadow map at the map's level of detail.
  void add_shadow_casters(std::vector<view::ShadowCaster>& casters) const override;
  void draw_shadow(const FrameInfo& frame) override;

  // ---- Controls ----
  void regrow(std::uint64_t seed);          // a new tree (same depth and height); waits for the device
  void set_bend_mode(tree::TreeBend mode);
  void set_draw_mode(tree::TreeDraw mode);
  void set_leaves(bool leaves);
  // On by default. Off: every level as tubes whatever the distance (the tests compare the two).
  void set_level_of_detail(bool on);

  // ---- Inspection (tests, the demo's panel) ----
  const tree::TreeSpec& spec() const;
  const tree::Tree& tree() const;
  // Each instance's frame as the next draw() pushes it (tree units).
  std::vector<tree::TreeWindFrame> wind_frames() const;
  // Each instance's level of detail in the last prepared frame: the thinnest level drawn as tubes
  // (the levels below it as twig lines; 1: all tubes). Meaningful for the tubes draw mode.
  std::vector<int> thinnest_tube_levels() const;
  std::vector<bool> diamond_leaves() const;  // false: one triangle a leaf (far)
  TreeDrawStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pond::render
