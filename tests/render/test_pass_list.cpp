// The frame's passes as parts (render/frame_pass.h): the barriers between them come from what they
// declare (no device needed to check those), and a frame with every effect off records no pass
// before the main one and makes none of their targets, while turning them on makes and runs each.
#include <cstdio>

#include "core/errors.h"
#include "drawn_session.h"
#include "golden.h"
#include "gpu_fixture.h"
#include "render/body_drawable.h"
#include "render/frame_pass.h"
#include "render/render_layout.h"
#include "render/render_target.h"
#include "render/water_pipeline.h"
#include "scene/scene.h"

namespace pond::test {
namespace {

using render::PassDeclaration;
using L = vk::ImageLayout;

vk::Image fake_image(std::uint64_t n) { return vk::Image(reinterpret_cast<VkImage>(n)); }
vk::Buffer fake_buffer(std::uint64_t n) { return vk::Buffer(reinterpret_cast<VkBuffer>(n)); }

render::PassWrite colour_write(vk::Image image) {
  return {.image = image, .layout = L::eColorAttachmentOptimal, .stages = render::S2::eColorAttachmentOutput,
          .access = render::A2::eColorAttachmentWrite};
}

const vk::MemoryBarrier2 kBefore{.srcStageMask = render::S2::eComputeShader, .dstStageMask = render::S2::eVertexShader};

TEST(PassBarriersTest, IndependentPassesShareOneBatchBeforeAndOneAfter) {
  PassDeclaration a, b;
  a.writes.push_back(colour_write(fake_image(1)));
  b.writes.push_back({.buffer = fake_buffer(2), .stages = render::S2::eComputeShader,
                      .access = render::A2::eShaderWrite, .read_stages = render::S2::eVertexShader,
                      .read_access = render::A2::eShaderRead});
  b.writes.push_back({.image = fake_image(3), .aspect = vk::ImageAspectFlagBits::eDepth,
                      .layout = L::eDepthAttachmentOptimal, .stages = render::S2::eLateFragmentTests,
                      .access = render::A2::eDepthStencilAttachmentWrite, .scratch = true});
  const PassDeclaration both[] = {a, b};
  const render::PassBarriers p = render::plan_pass_barriers(both, kBefore);
  ASSERT_EQ(p.before.size(), 2u);
  // Before: the frame's dependency and the buffer's (a memory barrier each), both images.
  EXPECT_EQ(p.before[0].memory.size(), 2u);
  ASSERT_EQ(p.before[0].images.size(), 2u);
  EXPECT_EQ(p.before[0].images[0].newLayout, L::eColorAttachmentOptimal);
  EXPECT_EQ(p.before[0].images[0].oldLayout, L::eUndefined);  // rewritten whole
  EXPECT_TRUE(p.before[1].memory.empty() && p.before[1].images.empty());
  // After: the colour image to shader-read and the buffer to the vertex shader; the scratch depth
  // nowhere.
  ASSERT_EQ(p.after.images.size(), 1u);
  EXPECT_EQ(p.after.images[0].image, fake_image(1));
  EXPECT_EQ(p.after.images[0].newLayout, L::eShaderReadOnlyOptimal);
  ASSERT_EQ(p.after.memory.size(), 1u);
  EXPECT_EQ(p.after.memory[0].dstStageMask, render::S2::eVertexShader);
}

TEST(PassBarriersTest, APassReadingAnEarlierOutputGetsABatchOfItsOwn) {
  PassDeclaration a, b;
  a.writes.push_back(colour_write(fake_image(1)));
  b.reads.push_back({.image = fake_image(1), .stages = render::S2::eComputeShader});
  b.writes.push_back(colour_write(fake_image(2)));
  const PassDeclaration both[] = {a, b};
  const render::PassBarriers p = render::plan_pass_barriers(both, kBefore);
  // Before a: image 1 to be written. Before b: image 1 readable (by b's compute and later the
  // fragment shader), image 2 to be written. After: image 2 readable.
  ASSERT_EQ(p.before[0].images.size(), 1u);
  ASSERT_EQ(p.before[1].images.size(), 2u);
  EXPECT_EQ(p.before[1].images[0].image, fake_image(1));
  EXPECT_EQ(p.before[1].images[0].oldLayout, L::eColorAttachmentOptimal);
  EXPECT_EQ(p.before[1].images[0].newLayout, L::eShaderReadOnlyOptimal);
  EXPECT_TRUE(p.before[1].images[0].dstStageMask & render::S2::eComputeShader);
  EXPECT_EQ(p.before[1].images[1].image, fake_image(2));
  ASSERT_EQ(p.after.images.size(), 1u);
  EXPECT_EQ(p.after.images[0].image, fake_image(2));
}

// An island (shadows on the floor, walls under the water) and a floating ball (a caster, something
// submerged), drawn with every effect off, then with every effect on.
const char* kEveryPass = R"({"grid": {"rows": 49, "cols": 49},
  "constraints": [{"kind": "fixed", "rows": [30, 36], "cols": [30, 36]}],
  "perturbations": [{"step": 0, "row": 14, "col": 14, "radius": 2.0, "amplitude": 1.0}],
  "bodies": [{"shape": "sphere", "radius": 2.5, "motion": "floating", "mass": 20.0,
              "position": [20.0, 1.0, 24.0]}]})";

class PassListTest : public GpuTest {};

TEST_F(PassListTest, EverythingOffRecordsNoPassAndMakesNoTarget) {
  DrawnSession d(ctx(), scene::parse_scene(kEveryPass, "test"), {}, render::RenderTarget::kFormat);
  render::BodyDrawable bodies(ctx(), d.loop);
  d.loop.add_drawable(bodies);
  render::RenderTarget target(ctx(), kWidth, kHeight);
  render::FrameView view;
  view.camera = d.loop.default_camera(kWidth, kHeight);
  view.wait = true;
  // Three frames with `effects`, then which passes the last one recorded.
  auto passes_run = [&](const view::Effects& effects) {
    view.effects = effects;
    for (int k = 0; k < 3; ++k) {
      d.session.advance(2);
      d.loop.frame(target.frame_target(), view);
    }
    return d.loop.passes_recorded();
  };
  const std::vector<std::string>& names = d.loop.timestamps().names();
  ASSERT_EQ(names.size(), 6u);  // caustics, foam, shadow, reflection, submerged, main
  EXPECT_EQ(names.back(), "main");
  const render::PassSet off = passes_run(view::Effects::none());
  ASSERT_EQ(off.size(), names.size());
  for (std::size_t p = 0; p < names.size(); ++p) EXPECT_EQ(off[p], names[p] == "main") << names[p];
  EXPECT_EQ(d.loop.pass_targets(), 0u);

  // Every effect on: each pass runs and has made its targets.
  const render::PassSet on = passes_run(view::Effects{});
  ASSERT_EQ(on.size(), names.size());
  for (std::size_t p = 0; p < names.size(); ++p) EXPECT_TRUE(on[p]) << names[p];
  EXPECT_TRUE(d.loop.recorded("foam") && d.loop.recorded("main"));
  EXPECT_FALSE(d.loop.recorded("no such pass"));
  // Where the device has timestamps, they time just those.
  if (d.loop.timestamps().supported()) {
    EXPECT_EQ(d.loop.timestamps().last().ran, on);
  }
  std::printf("targets the passes made with every effect on: %zu\n", d.loop.pass_targets());
  EXPECT_EQ(d.loop.pass_targets(), 3u + 6u * render::kFramesInFlight);
}

// A pass's binding in the water's set that another already has (the set's own, or another pass's)
// is refused when the pipelines are made, not left to clobber a descriptor.
TEST_F(PassListTest, ABindingOfTheWatersSetTakenTwiceIsRefused) {
  const vk::DescriptorSetLayoutBinding foamlike{.binding = POND_RENDER_BINDINGS,
                                                .descriptorType = vk::DescriptorType::eStorageBuffer,
                                                .descriptorCount = 1, .stageFlags = vk::ShaderStageFlagBits::eVertex};
  vk::DescriptorSetLayoutBinding state = foamlike;
  state.binding = POND_RENDER_BINDING_STATE;
  const vk::DescriptorSetLayoutBinding twice[] = {foamlike, foamlike};
  const auto make = [&](std::span<const vk::DescriptorSetLayoutBinding> b) {
    return render::create_water_pipelines(ctx(), render::RenderTarget::kFormat, render::kDepthFormat, b);
  };
  EXPECT_THROW(make(std::span(&state, 1)), InternalError);
  EXPECT_THROW(make(twice), InternalError);
}

}  // namespace
}  // namespace pond::test
