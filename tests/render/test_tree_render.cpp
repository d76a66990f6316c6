// The wind tree on the GPU (labels image, gpu; validation on, any message fails):
//  - parity: shared/tree_pose.h, the code tree.vert runs for the length-preserving bend and the
//    same tree_wind_bend it runs for the article's, executed for every skeleton vertex in a compute
//    shader (tree_pose.comp) equals the CPU evaluation (src/tree/bend.cpp) bit for bit, in both
//    modes, calm and gusty, up to depth 10 (the longest ancestor walk);
//  - golden images (256x160, tolerance as test_render.cpp) of the tree in calm air and in wind at a
//    fixed time, as lines and as tubes with leaves, and the length-preserving bend;
//  - instances sway out of step; the wind ripples are deterministic and land on water.
// Regenerate the goldens after a deliberate change: POND_REGENERATE_GOLDENS=1 ctest -L image.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "drawn_session.h"
#include "render/frame_loop.h"
#include "core/png.h"
#include "render/render_target.h"
#include "render/tree_drawable.h"
#include "tree/tree_mesh.h"
#include "sim/wind_ripples.h"
#include "gpu_fixture.h"
#include "golden.h"
#include "image_compare.h"
#include "shared/tree_render.h"
#include "scene/scene.h"
#include "tree/bend.h"
#include "tree/noise.h"

namespace pond::test {
namespace {

#include "tree_pose_comp.spv.h"

namespace sh = shared::tree_wind;

// ---- Parity --------------------------------------------------------------------------------------

class TreeParityTest : public GpuTest {
 protected:
  // Every vertex of `t` bent on the GPU by tree_pose.comp for `frame`.
  std::vector<tree::Vec3> gpu_pose(const tree::Tree& t, const tree::TreeWindFrame& frame) {
    using BU = vk::BufferUsageFlagBits;
    const gpu::Buffer skeleton = gpu::create_buffer(ctx(), t.size() * sizeof(tree::TreeVertex),
                                                    BU::eStorageBuffer | BU::eTransferDst, gpu::MemoryUse::device,
                                                    "skeleton");
    gpu::upload(ctx(), skeleton, std::as_bytes(std::span(t.vertices)));
    const gpu::Buffer parents = gpu::create_buffer(ctx(), t.size() * 4, BU::eStorageBuffer | BU::eTransferDst,
                                                   gpu::MemoryUse::device, "parents");
    gpu::upload(ctx(), parents, std::as_bytes(std::span(t.parents)));
    const gpu::Buffer out = gpu::create_buffer(ctx(), t.size() * 12, BU::eStorageBuffer, gpu::MemoryUse::readback, "bent");
    // Bindings 0..3: 0 is the renderer's frame uniform, which the pose does not read: bound to the
    // parents buffer only to make the set complete.
    const gpu::ComputePipeline pipe =
        gpu::create_compute_pipeline(ctx(), pond_spirv_tree_pose_comp, 4, sizeof(sh::TreeInstance), {}, "tree pose");
    const vk::raii::DescriptorPool pool(
        ctx().device(), vk::DescriptorPoolCreateInfo{
                            .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, .maxSets = 1, .poolSizeCount = 1,
                            .pPoolSizes = std::array{vk::DescriptorPoolSize{vk::DescriptorType::eStorageBuffer, 4}}.data()});
    const vk::DescriptorSetLayout layout = *pipe.set_layout;
    const vk::raii::DescriptorSet set = std::move(vk::raii::DescriptorSets(
        ctx().device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool, .descriptorSetCount = 1, .pSetLayouts = &layout})[0]);
    const vk::DescriptorBufferInfo infos[] = {parents.whole(), skeleton.whole(), parents.whole(), out.whole()};
    std::vector<vk::WriteDescriptorSet> writes;
    for (std::uint32_t b = 0; b < 4; ++b)
      writes.push_back({.dstSet = *set, .dstBinding = b, .descriptorCount = 1,
                        .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[b]});
    ctx().device().updateDescriptorSets(writes, nullptr);
    const sh::TreeInstance push{.base = {0, 0, 0, 1}, .wind = frame, .pruning = {1, 1, 0, 0}};
    ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
      cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipe.pipeline);
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipe.layout, 0, *set, nullptr);
      cmd.pushConstants<sh::TreeInstance>(*pipe.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
      cmd.dispatch(gpu::group_count(static_cast<std::uint32_t>(t.size()), POND_TREE_POSE_LOCAL_X), 1, 1);
      const vk::MemoryBarrier2 to_host{.srcStageMask = vk::PipelineStageFlagBits2::eComputeShader,
                                       .srcAccessMask = vk::AccessFlagBits2::eShaderWrite,
                                       .dstStageMask = vk::PipelineStageFlagBits2::eHost,
                                       .dstAccessMask = vk::AccessFlagBits2::eHostRead};
      cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
    });
    out.invalidate(ctx());
    std::vector<tree::Vec3> bent(t.size());
    std::memcpy(bent.data(), out.mapped, t.size() * 12);
    return bent;
  }

  // Bitwise comparison, reporting the first differing vertex.
  static void expect_same_bits(const std::vector<tree::Vec3>& cpu, const std::vector<tree::Vec3>& gpu,
                               const std::string& what) {
    ASSERT_EQ(cpu.size(), gpu.size());
    std::size_t differing = 0, first = 0;
    for (std::size_t i = 0; i < cpu.size(); ++i)
      if (std::memcmp(&cpu[i], &gpu[i], sizeof(tree::Vec3)) != 0 && differing++ == 0) first = i;
    EXPECT_EQ(differing, 0u) << what << ": " << differing << " of " << cpu.size() << " vertices differ, the first "
                             << first << ": CPU (" << cpu[first].x << ", " << cpu[first].y << ", " << cpu[first].z
                             << ") GPU (" << gpu[first].x << ", " << gpu[first].y << ", " << gpu[first].z << ")";
  }
};

// The frames to compare: calm air, a steady wind along each axis and a diagonal one, and gusty
// frames with twig jitter from the wind state after a few seconds at several strengths.
std::vector<tree::TreeWindFrame> parity_frames(tree::BendMode mode) {
  std::vector<tree::TreeWindFrame> frames;
  auto steady = [&](float x, float z) {
    tree::TreeWindFrame f{};
    f.wind = {x, 0, z, 0};
    f.bend_mode = static_cast<std::uint32_t>(mode);
    frames.push_back(f);
  };
  steady(0, 0);
  steady(0.45f, 0);
  steady(0, -0.3f);
  steady(-0.2f, 0.35f);
  const tree::NoiseTable noise = tree::make_noise_table(1);
  for (float strength : {1.0f, 5.0f, 9.0f}) {
    tree::UserWind user{.strength = strength, .direction = 0.7f};
    tree::WindState state;
    state.phase = tree::instance_phase(2);
    for (int k = 0; k < 90; ++k) tree::advance_wind(state, noise, user, 1.0 / 30.0);
    frames.push_back(tree::wind_frame(state, noise, user, mode));
  }
  return frames;
}

TEST_F(TreeParityTest, GpuBendEqualsTheCpuBitForBit) {
  for (int depth : {8, 10}) {
    const tree::Tree t = tree::grow_tree({.depth = depth, .seed = 3});
    for (tree::BendMode mode : {tree::BendMode::article, tree::BendMode::keep_length}) {
      const auto frames = parity_frames(mode);
      // Not a trivial agreement: the windy frames move the crown (tip of the last twig) off its rest.
      EXPECT_GT(std::abs(tree::bend_tree(t, frames[1]).back().x - t.vertices.back().position.x), 0.01f);
      for (std::size_t k = 0; k < frames.size(); ++k)
        expect_same_bits(tree::bend_tree(t, frames[k]), gpu_pose(t, frames[k]),
                         "depth " + std::to_string(depth) +
                             (mode == tree::BendMode::article ? " article" : " keep-length") + " frame " +
                             std::to_string(k));
    }
  }
}

// ---- Pictures ------------------------------------------------------------------------------------

// The default scene's island with a tree, no splash (so the pictures show the tree, not the
// rings), looked at from the pond at the tree's middle height.
std::string tree_scene(const std::string& tree, const std::string& wind) {
  return R"({"constraints": [{"kind": "fixed", "rows": [30, 35], "cols": [30, 36]}],
    "camera": {"eye": [33, 4.4, 50], "target": [35.5, 3.9, 32.5], "fovy": 40},
    "tree": )" + tree + R"(, "wind": )" + wind + "}";
}

class TreeRenderTest : public GpuTest {
 protected:
  // Renders the scene after `steps` steps (the wind clock: steps * dt simulated seconds).
  Rgba render(const std::string& json, std::int64_t steps, render::FrameStats* stats = nullptr, int frames = 1) {
    const scene::Scene scene = scene::parse_scene(json, "test");
    DrawnSession drawn(ctx(), scene, {}, render::RenderTarget::kFormat);
    render::FrameLoop& loop = drawn.loop;
    render::TreeDrawable tree(ctx(), loop, *scene.tree);
    loop.add_drawable(tree);
    render::RenderTarget target(ctx(), kWidth, kHeight);
    drawn.session.advance(steps);
    drawn.session.catch_up_wind();
    render::FrameView view;
    view.camera = loop.default_camera(kWidth, kHeight);
    view.wait = true;
    for (int f = 0; f < frames; ++f) {
      const render::FrameStats s = loop.frame(target.frame_target(), view);
      if (stats) *stats = s;
    }
    EXPECT_NEAR(drawn.session.wind().time(), static_cast<double>(steps) * scene.physics.dt, 1e-9);
    return Rgba{kWidth, kHeight, target.read_rgba()};
  }
};

constexpr std::int64_t kWindSteps = 25;  // 10 s of wind: the inertial wind has caught up with the gusts
const char* kLines = R"({"depth": 7, "draw": "lines", "leaves": false})";
const char* kTubes = R"({"depth": 7, "draw": "tubes", "leaves": true})";
const char* kCalm = R"({"strength": 0})";
const char* kWind = R"({"strength": 5, "direction_deg": 0})";

TEST_F(TreeRenderTest, LinesInCalmAir) { expect_golden("tree_lines_calm", render(tree_scene(kLines, kCalm), kWindSteps)); }
TEST_F(TreeRenderTest, LinesInWind) { expect_golden("tree_lines_wind", render(tree_scene(kLines, kWind), kWindSteps)); }
TEST_F(TreeRenderTest, TubesInCalmAir) { expect_golden("tree_tubes_calm", render(tree_scene(kTubes, kCalm), kWindSteps)); }
TEST_F(TreeRenderTest, TubesInWind) { expect_golden("tree_tubes_wind", render(tree_scene(kTubes, kWind), kWindSteps)); }

// The length-preserving bend draws a different tree from the article's in the same wind (the
// article's stretches), and the same picture in calm air (up to the rounding of rescaling every
// segment to its rest length, a few ulps).
TEST_F(TreeRenderTest, KeepLengthBend) {
  const std::string keep = R"({"depth": 7, "draw": "tubes", "leaves": true, "bend": "keep-length"})";
  const Rgba img = render(tree_scene(keep, kWind), kWindSteps);
  expect_golden("tree_tubes_wind_keep_length", img);
  EXPECT_GT(compare(render(tree_scene(kTubes, kWind), kWindSteps), img, kGoldenLevels).share, 0.002);
  EXPECT_LE(compare(render(tree_scene(kTubes, kCalm), kWindSteps), render(tree_scene(keep, kCalm), kWindSteps), kGoldenLevels).share,
            kGoldenShare);
}

// Wind moves the tree: the calm and windy pictures differ, and so do two times in the wind.
TEST_F(TreeRenderTest, WindMovesTheTreeOverTime) {
  const Rgba calm = render(tree_scene(kLines, kCalm), kWindSteps);
  const Rgba a = render(tree_scene(kLines, kWind), kWindSteps);
  const Rgba b = render(tree_scene(kLines, kWind), kWindSteps + 3);
  EXPECT_GT(compare(calm, a, kGoldenLevels).share, 0.002);
  EXPECT_GT(compare(a, b, kGoldenLevels).share, 0.0005);
}

// Two instances of the same tree under the same wind sway out of step (instance_phase).
TEST_F(TreeRenderTest, InstancesSwayOutOfStep) {
  const scene::Scene scene = scene::parse_scene(
      tree_scene(R"({"depth": 5, "positions": [[31, 31], [34, 35]]})", kWind), "test");
  DrawnSession drawn(ctx(), scene, {}, render::RenderTarget::kFormat);
  render::FrameLoop& loop = drawn.loop;
  render::TreeDrawable tree(ctx(), loop, *scene.tree);
  loop.add_drawable(tree);
  render::RenderTarget target(ctx(), kWidth, kHeight);
  render::FrameView view;
  view.camera = loop.default_camera(kWidth, kHeight);
  view.wait = true;
  for (int f = 0; f < 10; ++f) {  // a step a frame, the wind's clock the simulated time
    drawn.session.advance(1);
    drawn.session.catch_up_wind();
    loop.frame(target.frame_target(), view);
  }
  const auto frames = tree.wind_frames();
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_NE(frames[0].wind.x, frames[1].wind.x);
  EXPECT_NE(frames[0].twig.x, frames[1].twig.x);
  EXPECT_EQ(tree.stats().instances, 2u);
}

// The controls (the tree's and the session's wind) change what the next frame draws; regrow gives
// another tree of the same size.
TEST_F(TreeRenderTest, ControlsAndRegrow) {
  const scene::Scene scene = scene::parse_scene(tree_scene(kTubes, kCalm), "test");
  DrawnSession drawn(ctx(), scene, {}, render::RenderTarget::kFormat);
  render::FrameLoop& loop = drawn.loop;
  render::TreeDrawable tree(ctx(), loop, *scene.tree);
  loop.add_drawable(tree);
  render::RenderTarget target(ctx(), kWidth, kHeight);
  render::FrameView view;
  view.camera = loop.default_camera(kWidth, kHeight);
  view.wait = true;
  drawn.session.advance(1);
  drawn.session.catch_up_wind();
  loop.frame(target.frame_target(), view);
  const Rgba before{kWidth, kHeight, target.read_rgba()};
  drawn.session.set_wind_strength(12);  // clamped to 9
  EXPECT_EQ(drawn.session.wind().spec().strength, 9.0);
  drawn.session.set_wind_direction(1.0);
  tree.set_bend_mode(tree::TreeBend::keep_length);
  tree.set_draw_mode(tree::TreeDraw::lines);
  tree.set_leaves(false);
  drawn.session.advance_wind(2.0);  // the demo's clock: wall time
  loop.frame(target.frame_target(), view);
  EXPECT_NEAR(drawn.session.wind().time(), 2.0 + 0.4, 1e-9);  // the first frame's step, then 2 s by hand
  EXPECT_EQ(tree.wind_frames().at(0).bend_mode, sh::kTreeBendKeepLength);
  const Rgba after{kWidth, kHeight, target.read_rgba()};
  EXPECT_GT(compare(before, after, kGoldenLevels).share, 0.002);
  const std::size_t vertices = tree.tree().size();
  const float y = tree.tree().vertices.back().position.y;
  tree.regrow(99);
  EXPECT_EQ(tree.spec().seed, 99u);
  EXPECT_EQ(tree.tree().size(), vertices);
  EXPECT_NE(tree.tree().vertices.back().position.y, y);
  loop.frame(target.frame_target(), view);
}

// ---- Ripples (no GPU) ---------------------------------------------------------------------------

TEST(TreeRipples, DeterministicOnWaterAndOnlyInWind) {
  const scene::Scene scene = scene::parse_scene(tree_scene("{}", R"({"strength": 6, "ripples": true})"), "test");
  const sim::WaterModel model = sim::build_model(scene);
  const tree::NoiseTable noise = tree::make_noise_table(1);
  const auto user = tree::user_wind(scene.wind);
  const auto a = sim::wind_ripples(model, noise, user, 1, 0, 300);
  const auto b = sim::wind_ripples(model, noise, user, 1, 0, 300);
  ASSERT_EQ(a.size(), 100u);  // one every kRippleEverySteps
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].step, b[k].step);
    EXPECT_EQ(a[k].row, b[k].row);
    EXPECT_EQ(a[k].amplitude, b[k].amplitude);
    EXPECT_LT(a[k].amplitude, 0.0);
    EXPECT_GT(a[k].amplitude, -0.3 * 9 * tree::kWindPerStrength * 1.5 - 1e-9);
    const auto n = static_cast<std::size_t>(a[k].row) * model.cols + static_cast<std::size_t>(a[k].col);
    EXPECT_NE(model.kinds[n], static_cast<std::uint8_t>(sim::NodeKind::fixed));
  }
  // Split windows give the same ripples as one.
  auto first = sim::wind_ripples(model, noise, user, 1, 0, 151);
  const auto second = sim::wind_ripples(model, noise, user, 1, 151, 300);
  first.insert(first.end(), second.begin(), second.end());
  ASSERT_EQ(first.size(), a.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(first[k].step, a[k].step);
  tree::UserWind calm = user;
  calm.strength = 0;
  EXPECT_TRUE(sim::wind_ripples(model, noise, calm, 1, 0, 300).empty());
  // Only with "ripples": true does the scene gain perturbations.
  scene::Scene with = scene, without = scene::parse_scene(tree_scene("{}", R"({"strength": 6})"), "test");
  sim::add_wind_ripples(with, with.wind, 300);
  sim::add_wind_ripples(without, without.wind, 300);
  EXPECT_EQ(with.perturbations.size(), a.size());
  EXPECT_TRUE(without.perturbations.empty());
}

// The mesh: one line per segment, closed tubes, one leaf per thinnest twig (order and winding:
// test_tree_lod.cpp).
TEST(TreeMesh, CountsAndRanges) {
  const tree::Tree t = tree::grow_tree({.depth = 6, .seed = 1});
  const tree::TreeMesh m = tree::build_tree_mesh(t);
  EXPECT_EQ(m.lines.all.count, 2 * (t.size() - 1));
  std::size_t twigs = 0, thin = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    twigs += t.levels[i] == 1;
    thin += t.levels[i] <= 2;
  }
  EXPECT_EQ(m.leaves.count, 6 * twigs);
  EXPECT_EQ(m.leaf_triangles.count, 3 * twigs);
  EXPECT_EQ(m.leaf_triangles.first, m.leaves.first + m.leaves.count);
  EXPECT_EQ(m.tubes.all.count, 6 * (4 * thin + 6 * (t.size() - 1 - thin)));
  EXPECT_EQ(m.tubes.all.first, m.lines.all.count);
  EXPECT_EQ(m.leaves.first, m.tubes.all.first + m.tubes.all.count);
  for (std::uint32_t idx : m.indices) EXPECT_LT(idx, m.vertices.size());
  EXPECT_GT(m.rest_height, 1.0f);
  EXPECT_GT(tree::tree_tube_radius(6, 6), tree::tree_tube_radius(6, 1));
}

}  // namespace
}  // namespace pond::test
