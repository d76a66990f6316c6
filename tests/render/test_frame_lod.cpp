// The LOD a frame draws is built from the very state it draws (render/frame_loop.h): the frame's
// compute is submitted after its draw, so the positions on the host when the frame is prepared
// (sim::Solver::displacements, what the CPU waited for once) are bit for bit the GPU state the
// frame's passes read, and the LOD's tau bound holds on the surface actually drawn. Checked with
// the strict, independent checker of tests/lod on the GPU's own state read back after each frame,
// while rain, a run-time splash and the bodies move the water between frames. On a discrete GPU
// this is what lets frame N's LOD run without waiting for frame N's compute: the margin for the
// motion since is zero.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "drawn_session.h"
#include "gpu_fixture.h"
#include "lod/mesh_checker.h"
#include "render/body_drawable.h"
#include "render/render_target.h"
#include "scene/scene.h"
#include "sim/state.h"

namespace pond::test {
namespace {

using lod_test::CheckCamera;
using lod_test::ErrorReport;

// A 65 x 65 pond with an island, a splash every 3 steps, a dragged sphere and a floating ball.
std::string rain_scene() {
  std::string splashes;
  for (int k = 0; k < 12; ++k)
    splashes += (k ? ", " : "") + std::string("{\"step\": ") + std::to_string(3 * k) + ", \"row\": " +
                std::to_string(10 + (k * 17) % 45) + ", \"col\": " + std::to_string(8 + (k * 29) % 50) +
                ", \"radius\": 1.2, \"amplitude\": " + (k % 2 ? "0.6" : "-0.8") + "}";
  return R"({"grid": {"rows": 65, "cols": 65}, "physics": {"substeps": 2},
    "constraints": [{"kind": "fixed", "rows": [30, 36], "cols": [40, 46]}],
    "perturbations": [)" + splashes + R"(],
    "bodies": [{"motion": "kinematic", "radius": 3, "path": [[0, 10, 0.5, 20], [40, 50, 0.5, 24]]},
               {"motion": "floating", "radius": 2.5, "mass": 30, "position": [30, 2, 50]}]})";
}

class FrameLodTest : public GpuTest {};

TEST_F(FrameLodTest, TheLodOfEveryFrameHoldsTauOnTheDrawnSurface) {
  constexpr int kViewWidth = 480, kViewHeight = 300;
  constexpr double kTau = 1.0;
  const scene::Scene scene = scene::parse_scene(rain_scene(), "test");
  DrawnSession d(ctx(), scene, {}, render::RenderTarget::kFormat);
  render::BodyDrawable bodies(ctx(), d.loop);
  d.loop.add_drawable(bodies);
  render::RenderTarget target(ctx(), kViewWidth, kViewHeight);
  render::FrameView view;
  view.camera = d.loop.default_camera(kViewWidth, kViewHeight);
  view.lod_tolerance_px = kTau;
  const CheckCamera cam{view.camera.eye, view.camera.target, view.camera.fovy_degrees, kViewWidth, kViewHeight};
  const sim::WaterModel& model = d.session.model();
  const auto rows = static_cast<std::size_t>(model.rows), cols = static_cast<std::size_t>(model.cols);
  d.session.advance(2);
  std::size_t left_out = 0;
  for (int frame = 0; frame < 12; ++frame) {
    d.loop.frame(target.frame_target(), view);
    // Nothing was submitted since the frame: the session's state is the one it drew.
    const sim::WaterState drawn = d.session.state();
    const sim::HostDisplacements u = d.session.reader().displacements();
    int rows_differing = 0;
    for (std::size_t i = 0; i < rows; ++i)
      rows_differing += std::memcmp(u.ux + i * u.pitch, drawn.ux.data() + i * cols, cols * sizeof(float)) != 0 ||
                        std::memcmp(u.uy + i * u.pitch, drawn.uy.data() + i * cols, cols * sizeof(float)) != 0 ||
                        std::memcmp(u.uz + i * u.pitch, drawn.uz.data() + i * cols, cols * sizeof(float)) != 0;
    EXPECT_EQ(rows_differing, 0) << "frame " << frame << ": the LOD's positions are not the drawn state";
    const std::vector<std::uint32_t> tris(d.loop.lod_triangles().begin(), d.loop.lod_triangles().end());
    EXPECT_EQ(lod_test::topology_problem(tris, model.rows, model.cols), "") << "frame " << frame;
    const ErrorReport e =
        lod_test::screen_errors(tris, model.rows, model.cols, sim::to_world_interleaved(drawn, model), cam);
    EXPECT_EQ(e.uncovered, 0u) << "frame " << frame;
    EXPECT_LE(e.max_error_px, kTau) << "frame " << frame << ": " << e.left_out_in_view << " left-out nodes in view";
    left_out += e.left_out_in_view;
    if (frame == 5) d.session.splash({.row = 20, .col = 20, .radius = 2.0, .amplitude = 1.5});  // a click
    d.session.advance(2);  // the next frame's steps (the splash first), submitted after the draw as the demo does
  }
  EXPECT_GT(left_out, 0u) << "a LOD that leaves nothing out proves little";
}

}  // namespace
}  // namespace pond::test
