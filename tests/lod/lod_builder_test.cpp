// The LOD builder against the contract, checked by the independent checkers of mesh_checker.h.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "lod/lod_builder.h"
#include "lod/mesh_checker.h"
#include "lod/rippled_states.h"
#include "sim/cpu_solver.h"
#include "scene/scene.h"

namespace pond::lod_test {
namespace {

struct Built {
  std::vector<std::uint32_t> tris;
  lod::BuildStats stats;
};

Built build(const std::vector<float>& state, int rows, int cols, const CheckCamera& c, double tau) {
  lod::LodBuilder builder(rows, cols);
  std::vector<std::uint32_t> out(builder.max_indices());
  lod::Camera cam{c.eye, c.target, c.fovy_degrees, c.width, c.height};
  const std::size_t n = builder.build(lod::interleaved_positions(state.data(), rows, cols), cam, tau, out);
  out.resize(n);
  return {out, builder.stats()};
}

// Builds and holds the result to every check; returns the triangle count.
std::size_t build_and_check(const std::vector<float>& state, int rows, int cols,
                            const CheckCamera& cam, double tau, const std::string& what) {
  const Built b = build(state, rows, cols, cam, tau);
  EXPECT_EQ(topology_problem(b.tris, rows, cols), "") << what;
  const ErrorReport e = screen_errors(b.tris, rows, cols, state, cam);
  EXPECT_EQ(e.uncovered, 0u) << what;
  EXPECT_LE(e.max_error_px, tau) << what << ": " << e.left_out_in_view << " left-out nodes in view";
  return b.tris.size() / 3;
}

// Cameras around a rows x cols pond: near, far, grazing, from below, straight down, inside.
std::vector<std::pair<std::string, CheckCamera>> cameras(int rows, int cols) {
  const double cx = (cols - 1) / 2.0, cz = (rows - 1) / 2.0, size = std::max(rows, cols);
  return {
      {"near", {{cx, 2.0, cz - 3}, {cx, 0, cz + 5}, 60, 640, 480}},
      {"oblique", {{cx, 0.6 * size, -0.5 * size}, {cx, 0, cz}, 50, 1280, 720}},
      {"far", {{-3 * size, 2 * size, -3 * size}, {cx, 0, cz}, 30, 800, 600}},
      {"grazing", {{-2, 0.3, cz}, {cols + 10.0, 0.1, cz + 1}, 70, 1280, 720}},
      {"below", {{cx + 1, -0.4 * size, cz - 2}, {cx, 0, cz}, 90, 600, 800}},
      {"down", {{cx, 0.8 * size, cz}, {cx, 0, cz}, 60, 1024, 768}},
      {"narrow", {{cx, 3, -5}, {cx + 2, 0, cz}, 5, 300, 200}},
  };
}

void sweep(int rows, int cols, const std::vector<float>& state, const std::string& name) {
  for (const auto& [cam_name, cam] : cameras(rows, cols))
    for (double tau : {0.5, 1.0, 4.0})
      build_and_check(state, rows, cols, cam, tau,
                      name + " " + std::to_string(rows) + "x" + std::to_string(cols) + " " + cam_name +
                          " tau " + std::to_string(tau));
}

TEST(LodBuilder, TinyGridsAreValidFromEveryCamera) {
  for (auto [rows, cols] : {std::pair{2, 2}, {2, 5}, {5, 2}, {3, 3}, {3, 97}, {97, 3}, {4, 7}})
    sweep(rows, cols, analytic_ripples(rows, cols, 3, 0.5, 7u + static_cast<unsigned>(rows * cols)),
          "ripples");
}

TEST(LodBuilder, RectangularRippledGridsAreValidFromEveryCamera) {
  std::uint32_t seed = 11;
  for (auto [rows, cols] : {std::pair{17, 17}, {33, 20}, {20, 33}, {50, 50}, {65, 65}, {37, 100}})
    sweep(rows, cols, analytic_ripples(rows, cols, 6, 0.8, seed++), "ripples");
}

TEST(LodBuilder, SimulatedRainIsValidFromEveryCamera) {
  sweep(65, 65, simulated_pond(65, 65, 60, 6, 10, 3), "rain");
  sweep(49, 70, simulated_pond(49, 70, 20, 2, 25, 4), "splashes");
}

TEST(LodBuilder, RandomGridsCamerasAndTolerancesAreValid) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 60; ++trial) {
    const int rows = 2 + static_cast<int>(u(rng) * 70), cols = 2 + static_cast<int>(u(rng) * 70);
    const std::vector<float> s = analytic_ripples(rows, cols, 1 + trial % 7, 0.2 + u(rng), 100u + trial);
    const double span = std::max(rows, cols);
    CheckCamera cam{{(u(rng) * 3 - 1) * cols, (u(rng) * 2 - 0.7) * span, (u(rng) * 3 - 1) * rows},
                    {u(rng) * cols, u(rng) - 0.5, u(rng) * rows}, 5 + u(rng) * 120,
                    100 + static_cast<int>(u(rng) * 1800), 100 + static_cast<int>(u(rng) * 1000)};
    const double tau = 0.2 + 5 * u(rng);
    build_and_check(s, rows, cols, cam, tau, "random trial " + std::to_string(trial));
  }
}

// The issue's target case: a rain-covered 257^2 pond seen from 35 units up at 1280x720, tau = 1 px
// (the benchmark's "rain": one drop per 160 nodes over 20 steps): at most 4 % of the full mesh.
// And the same drops ten times stronger, which needs far more, still within tolerance.
TEST(LodBuilder, RainCoveredPondNeedsAtMostFourPercent) {
  const CheckCamera cam{{128, 35, -20}, {128, 0, 110}, 60, 1280, 720};
  const std::size_t full = 2u * 256 * 256;
  const std::size_t rain = build_and_check(simulated_pond(257, 257, 412, 20, 15, 1, 0.1), 257, 257,
                                           cam, 1.0, "rain 257");
  std::printf("rain-covered 257^2 at tau 1 px: %zu triangles, %.2f %% of %zu\n", rain,
              100.0 * static_cast<double>(rain) / static_cast<double>(full), full);
  EXPECT_LE(rain, full * 4 / 100);
  const std::size_t storm = build_and_check(simulated_pond(257, 257, 412, 20, 15, 1, 1.0), 257, 257,
                                            cam, 1.0, "storm 257");
  EXPECT_LT(storm, full / 4);
}

TEST(LodBuilder, FlatGridCollapsesToTwoTriangles) {
  // Any size: 2^k + 1 squares, and the others, whose clipped root triangles still give two when
  // the grid fits one root square. Grids with sides in different powers of two keep one root
  // square per (shorter side rounded up to a power of two) and its clipped fans: 100 x 37 has two
  // squares of side 64 clipped to 7 triangles, 129 x 200 two of 128 clipped to 5, 2 x 5 four unit
  // squares, 3 x 97 48 squares of side 2.
  struct Case { int rows, cols; std::size_t triangles; };
  for (const Case c : {Case{2, 2, 2}, {3, 3, 2}, {33, 33, 2}, {257, 257, 2}, {50, 50, 2},
                       {100, 37, 7}, {129, 200, 5}, {2, 5, 8}, {3, 97, 96}}) {
    const int rows = c.rows, cols = c.cols;
    const std::vector<float> s = flat_pond(rows, cols, 1.5);
    for (const auto& [name, cam] : cameras(rows, cols)) {
      if (name == "grazing") continue;  // the eye lies in the plane: nodes on the view ray
      const Built b = build(s, rows, cols, cam, 0.25);
      EXPECT_EQ(b.tris.size() / 3, c.triangles) << rows << "x" << cols << " " << name;
      EXPECT_EQ(topology_problem(b.tris, rows, cols), "");
    }
  }
}

TEST(LodBuilder, TinyToleranceGivesTheFullMesh) {
  for (auto [rows, cols] : {std::pair{2, 2}, {3, 97}, {33, 33}, {40, 23}}) {
    const std::vector<float> s = analytic_ripples(rows, cols, 5, 0.5, 21);
    const CheckCamera cam{{(cols - 1) / 2.0, 3.0 * std::max(rows, cols), (rows - 1) / 2.0 - 1},
                          {(cols - 1) / 2.0, 0, (rows - 1) / 2.0}, 90, 1000, 1000};
    const Built b = build(s, rows, cols, cam, 1e-7);
    EXPECT_EQ(b.tris.size() / 3, 2u * (rows - 1) * (cols - 1)) << rows << "x" << cols;
    EXPECT_EQ(topology_problem(b.tris, rows, cols), "");
  }
}

TEST(LodBuilder, NothingInViewCollapses) {
  const std::vector<float> s = analytic_ripples(65, 65, 8, 1.0, 2);
  const CheckCamera away{{32, 5, -10}, {32, 5, -20}, 60, 640, 480};  // looking away from the pond
  const Built b = build(s, 65, 65, away, 1.0);
  EXPECT_EQ(b.tris.size() / 3, 2u);
}

TEST(LodBuilder, SameInputGivesSameIndices) {
  const std::vector<float> s = analytic_ripples(65, 40, 8, 1.0, 9);
  const CheckCamera cam = cameras(65, 40)[1].second;
  EXPECT_EQ(build(s, 65, 40, cam, 1.0).tris, build(s, 65, 40, cam, 1.0).tris);
}

// A builder that has built other frames (whose blocks it tests on their nodes first, and which
// may read the whole grid) gives each frame the mesh a new builder gives it.
TEST(LodBuilder, FramesBeforeDoNotChangeTheMesh) {
  const int n = 257;
  const std::vector<float> states[2] = {simulated_pond(n, n, 400, 20, 10, 5), simulated_pond(n, n, 100, 5, 20, 6)};
  lod::LodBuilder builder(n, n);
  std::vector<std::uint32_t> out(builder.max_indices());
  int in_blocks = 0;
  for (int frame = 0; frame < 12; ++frame) {
    const std::vector<float>& state = states[frame / 4 % 2];
    const double x = 100.0 + 6.0 * frame;
    const CheckCamera cam{{x, 150.0 - 30 * (frame % 2), -80}, {x, 0, 128}, 60, 1280, 720};
    const lod::Camera c{cam.eye, cam.target, cam.fovy_degrees, cam.width, cam.height};
    const std::size_t count = builder.build(lod::interleaved_positions(state.data(), n, n), c, 1.0, out);
    in_blocks += !builder.stats().whole;
    EXPECT_EQ(std::vector<std::uint32_t>(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count)),
              build(state, n, n, cam, 1.0).tris)
        << "frame " << frame;
  }
  EXPECT_GE(in_blocks, 4);  // frames in blocks, after blocks and after the whole grid
  EXPECT_LE(in_blocks, 10);
}

TEST(LodBuilder, ReadsStructureOfArraysLikeInterleaved) {
  const int rows = 33, cols = 21;
  const std::vector<float> s = analytic_ripples(rows, cols, 5, 0.7, 4);
  std::vector<float> x, y, z;
  for (std::size_t n = 0; n < s.size() / 6; ++n)
    x.push_back(s[n * 6]), y.push_back(s[n * 6 + 1]), z.push_back(s[n * 6 + 2]);
  const CheckCamera c = cameras(rows, cols)[0].second;
  const lod::Camera cam{c.eye, c.target, c.fovy_degrees, c.width, c.height};
  lod::LodBuilder builder(rows, cols);
  std::vector<std::uint32_t> out(builder.max_indices());
  const std::size_t n = builder.build(lod::soa_positions(x.data(), y.data(), z.data(), rows, cols), cam, 1.0, out);
  out.resize(n);
  EXPECT_EQ(out, build(s, rows, cols, c, 1.0).tris);
}

// The renderer's view: the solver's displacements in grid units (grid_displacements), converted
// by the builder while it copies. The same triangles as the world positions computed the
// documented way, (col + ux) * h, uy * h, (row + uz) * h; 33 x 21 also runs the 4-wide path's
// scalar tail (21 = 5 x 4 + 1). A non-finite displacement is refused like a position.
TEST(LodBuilder, ReadsGridDisplacementsLikeWorldPositions) {
  const scene::Scene scene = scene::parse_scene(
      R"({"grid": {"rows": 33, "cols": 21, "spacing": 0.5},
          "perturbations": [{"step": 0, "row": 16, "col": 10, "radius": 2.0, "amplitude": 2.0},
                            {"step": 5, "row": 8, "col": 4.5, "radius": 1.5, "amplitude": 1.0,
                             "target": "position"}]})",
      "displacements");
  const sim::WaterModel model = sim::build_model(scene);
  sim::CpuSolver solver(model, sim::Backend::scalar, 1);
  solver.advance(40);
  sim::WaterState u = solver.state();
  const int rows = model.rows, cols = model.cols;
  const float h = model.spacing;
  std::vector<float> x, y, z;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const std::size_t n = static_cast<std::size_t>(i) * cols + j;
      x.push_back((static_cast<float>(j) + u.ux[n]) * h);
      y.push_back(u.uy[n] * h);
      z.push_back((static_cast<float>(i) + u.uz[n]) * h);
    }
  lod::LodBuilder builder(rows, cols);
  std::vector<std::uint32_t> world(builder.max_indices()), displaced(builder.max_indices());
  for (const auto& [name, c] : cameras(rows, cols)) {
    const lod::Camera cam{{c.eye[0] * h, c.eye[1] * h, c.eye[2] * h}, {c.target[0] * h, c.target[1] * h, c.target[2] * h},
                          c.fovy_degrees, c.width, c.height};
    world.resize(builder.build(lod::soa_positions(x.data(), y.data(), z.data(), rows, cols), cam, 0.5, world));
    displaced.resize(builder.build(
        lod::grid_displacements(u.ux.data(), u.uy.data(), u.uz.data(), rows, cols, h), cam, 0.5, displaced));
    EXPECT_EQ(displaced, world) << name;
    EXPECT_LT(world.size(), 6u * (rows - 1) * (cols - 1)) << name << ": a full mesh proves little";
    world.resize(builder.max_indices()), displaced.resize(builder.max_indices());
  }
  u.uz[7 * cols + 20] = std::numeric_limits<float>::infinity();
  const CheckCamera c = cameras(rows, cols)[0].second;
  EXPECT_THROW(builder.build(lod::grid_displacements(u.ux.data(), u.uy.data(), u.uz.data(), rows, cols, h),
                             lod::Camera{c.eye, c.target, c.fovy_degrees, c.width, c.height}, 1.0, world),
               InputError);
}

// Views of rows padded to a pitch (the GPU solver's state read in place: rows of cols nodes,
// pitch nodes apart) give the same triangles as the compact arrays; the padding (NaN here) is
// never read. Covers the displacement copy (4-wide and tail) and the plain SoA and interleaved
// copies (one run per row).
TEST(LodBuilder, ReadsPaddedRowsLikeCompactOnes) {
  const scene::Scene scene = scene::parse_scene(
      R"({"grid": {"rows": 19, "cols": 21, "spacing": 0.5},
          "perturbations": [{"step": 0, "row": 9, "col": 10, "radius": 2.0, "amplitude": 2.0}]})",
      "padded");
  const sim::WaterModel model = sim::build_model(scene);
  sim::CpuSolver solver(model, sim::Backend::scalar, 1);
  solver.advance(30);
  const sim::WaterState u = solver.state();
  const int rows = model.rows, cols = model.cols;
  const std::size_t pitch = 24;
  const float h = model.spacing, nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> x, y, z;  // world positions, compact
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const std::size_t n = static_cast<std::size_t>(i) * cols + j;
      x.push_back((static_cast<float>(j) + u.ux[n]) * h);
      y.push_back(u.uy[n] * h);
      z.push_back((static_cast<float>(i) + u.uz[n]) * h);
    }
  // pad(a): a's rows copied pitch floats apart, NaN between; records: x, y, z, NaN x 3, padded too.
  auto pad = [&](const auto& a) {
    std::vector<float> p(rows * pitch, nan);
    for (int i = 0; i < rows; ++i) std::copy_n(a.data() + i * cols, cols, p.begin() + i * pitch);
    return p;
  };
  const std::vector<float> pux = pad(u.ux), puy = pad(u.uy), puz = pad(u.uz), px = pad(x), py = pad(y), pz = pad(z);
  std::vector<float> records(rows * pitch * 6, nan);
  for (std::size_t k = 0; k < rows * pitch; ++k) records[6 * k] = px[k], records[6 * k + 1] = py[k], records[6 * k + 2] = pz[k];
  lod::NodePositions soa = lod::soa_positions(px.data(), py.data(), pz.data(), rows, cols);
  soa.row_pitch = pitch;
  lod::NodePositions interleaved = lod::interleaved_positions(records.data(), rows, cols);
  interleaved.row_pitch = pitch;
  const std::pair<const char*, lod::NodePositions> views[] = {
      {"displacements", lod::grid_displacements(pux.data(), puy.data(), puz.data(), rows, cols, h, pitch)},
      {"SoA", soa},
      {"interleaved", interleaved}};
  lod::LodBuilder builder(rows, cols);
  std::vector<std::uint32_t> compact(builder.max_indices()), padded(builder.max_indices());
  for (const auto& [name, c] : cameras(rows, cols)) {
    const lod::Camera cam{{c.eye[0] * h, c.eye[1] * h, c.eye[2] * h}, {c.target[0] * h, c.target[1] * h, c.target[2] * h},
                          c.fovy_degrees, c.width, c.height};
    compact.resize(builder.build(lod::soa_positions(x.data(), y.data(), z.data(), rows, cols), cam, 0.5, compact));
    EXPECT_LT(compact.size(), 6u * (rows - 1) * (cols - 1)) << name << ": a full mesh proves little";
    for (const auto& [view_name, view] : views) {
      padded.resize(builder.max_indices());
      padded.resize(builder.build(view, cam, 0.5, padded));
      EXPECT_EQ(padded, compact) << name << ", " << view_name;
    }
    compact.resize(builder.max_indices());
  }
}

TEST(LodBuilder, RejectsBadInput) {
  const std::vector<float> s = flat_pond(9, 9);
  lod::LodBuilder builder(9, 9);
  std::vector<std::uint32_t> out(builder.max_indices());
  const auto view = lod::interleaved_positions(s.data(), 9, 9);
  const lod::Camera good{{4, 5, -3}, {4, 0, 4}, 60, 640, 480};
  EXPECT_NO_THROW(builder.build(view, good, 1.0, out));
  lod::Camera c = good;
  c.fovy_degrees = 180;
  EXPECT_THROW(builder.build(view, c, 1.0, out), InputError);
  c = good, c.target = c.eye;
  EXPECT_THROW(builder.build(view, c, 1.0, out), InputError);
  c = good, c.width = 0;
  EXPECT_THROW(builder.build(view, c, 1.0, out), InputError);
  EXPECT_THROW(builder.build(view, good, 0.0, out), InputError);
  EXPECT_THROW(builder.build(lod::interleaved_positions(s.data(), 3, 27), good, 1.0, out), InternalError);
  std::vector<std::uint32_t> small(out.size() - 1);
  EXPECT_THROW(builder.build(view, good, 1.0, small), InternalError);
  std::vector<float> bad = s;
  bad[40 * 6 + 1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(builder.build(lod::interleaved_positions(bad.data(), 9, 9), good, 1.0, out), InputError);
  EXPECT_THROW(lod::LodBuilder(1, 5), InternalError);
}

// The paper's figure 8: its 50 x 50 pond (the default scene: a splash beside an island) rippling,
// seen obliquely from above. Paper: 4802 triangles full, 2431 simplified.
TEST(LodBuilder, PapersFigureEightCase) {
  sim::CpuSolver solver(sim::build_model(scene::load_scene("")), sim::Backend::scalar, 1);
  solver.advance(60);
  const std::vector<float> s = sim::to_world_interleaved(solver.state(), solver.model());
  const CheckCamera cam{{24.5, 28, -22}, {24.5, 0, 26}, 60, 1024, 768};
  for (double tau : {0.5, 1.0, 2.0}) {
    const std::size_t t = build_and_check(s, 50, 50, cam, tau, "figure 8");
    std::printf("paper's 50x50 case at tau %.1f px: %zu triangles (full 4802, paper 2431)\n", tau, t);
    if (tau == 1.0) {
      EXPECT_LT(t, 2431u);
    }
  }
}

}  // namespace
}  // namespace pond::lod_test

namespace pond::lod_test {
namespace {

// The checkers themselves must be able to fail: broken meshes are caught.
TEST(MeshChecker, CatchesBrokenMeshes) {
  const int rows = 3, cols = 3;  // nodes 0..8, row-major
  // Full mesh of the 2 x 2 cells, rest normal +y (a, c, d and a, d, b per cell).
  std::vector<std::uint32_t> full = {0, 3, 4, 0, 4, 1, 1, 4, 5, 1, 5, 2,
                                     3, 6, 7, 3, 7, 4, 4, 7, 8, 4, 8, 5};
  EXPECT_EQ(topology_problem(full, rows, cols), "");
  std::vector<std::uint32_t> missing(full.begin(), full.end() - 3);
  EXPECT_NE(topology_problem(missing, rows, cols), "");
  std::vector<std::uint32_t> flipped = full;
  std::swap(flipped[1], flipped[2]);
  EXPECT_NE(topology_problem(flipped, rows, cols), "");
  // A T-junction: the right column as two big triangles whose edge 1-7 runs through node 4,
  // a vertex of the left column's triangles. Area and orientation are fine; pairing is not.
  const std::vector<std::uint32_t> t_junction = {0, 3, 4, 0, 4, 1, 3, 6, 7, 3, 7, 4,
                                                 1, 7, 8, 1, 8, 2};
  EXPECT_NE(topology_problem(t_junction, rows, cols), "");
  // Two triangles over a rippled surface: the centre node is far off.
  std::vector<float> s = flat_pond(rows, cols);
  s[4 * 6 + 1] = 0.5f;
  const std::vector<std::uint32_t> coarse = {0, 6, 8, 0, 8, 2};
  EXPECT_EQ(topology_problem(coarse, rows, cols), "");
  const CheckCamera cam{{1, 5, -3}, {1, 0, 1}, 60, 640, 480};
  const ErrorReport e = screen_errors(coarse, rows, cols, s, cam);
  EXPECT_EQ(e.left_out, 5u);
  EXPECT_GT(e.max_error_px, 10.0);
}

}  // namespace
}  // namespace pond::lod_test
