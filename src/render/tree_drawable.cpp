#include "render/tree_drawable.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <string>

#include "gpu/buffer.h"
#include "tree/tree_lod.h"
#include "tree/tree_mesh.h"
#include "render/frame_constants.h"
#include "render/reflection_pass.h"
#include "render/shadow_pass.h"
#include "render/tree_pipeline.h"
#include "shared/tree_render.h"
#include "tree/bend.h"
#include "tree/noise.h"
#include "tree/wind.h"

namespace pond::render {
namespace {

namespace sh = shared::tree_wind;
using BU = vk::BufferUsageFlagBits;

// Linear colours: dark bark, a summer green, and the article's near-black lines.
constexpr sh::vec4 kBark{0.16f, 0.1f, 0.06f, 0.0f};
constexpr sh::vec4 kLeaf{0.09f, 0.24f, 0.045f, 0.0f};
constexpr sh::vec4 kLine{0.05f, 0.04f, 0.03f, 1.0f};

// The shadow map's level of detail is chosen as for a map with this share of its texels per unit:
// coarser (fewer tube levels, more of the far leaves pruned, the rest grown to cover the same
// area), since the tree's vertex work, not the map's few texels, is what its pass costs.
constexpr float kShadowLodScale = 0.5f;
// The planar reflection's, relative to its own pixels: the ripples shift and the Fresnel term
// dims its image, so its tree is pruned as one twice as far away.
constexpr float kMirroredLodScale = 0.5f;

sh::vec4 v4(const std::array<double, 3>& a) {
  return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2]), 0.0f};
}

// An instance's level of detail at one pixel density: the thinnest level drawn as tubes and the
// leaves' shape and pruning.
struct InstanceLod {
  int thinnest_tube = 1;
  bool diamond_leaves = true;
  tree::Pruning leaves;              // of the far leaves' triangles (used when not diamonds)
  std::vector<tree::Pruning> twigs;  // of each twig-line level below thinnest_tube (index: level)
};

struct Instance {
  sh::vec4 base;  // foot (world) and scale
  // This frame's (prepare()): the wind pushed to the shader (the session's), and the level of detail for the frame
  // and for the planar reflection, whose pixels are kReflectionDivisor times larger: its image is
  // pruned as a tree that far away would be, and kMirroredLodScale more.
  tree::TreeWindFrame frame{};
  InstanceLod lod, mirrored_lod;
  InstanceLod shadow_lod;  // the sun's shadow map's level of detail (draw_shadow())
};

struct SlotResources {
  gpu::Buffer uniforms;
  vk::raii::DescriptorSet set = nullptr;
};

}  // namespace

struct TreeDrawable::Impl {
  const gpu::Context& ctx;
  const sim::Session& session;  // the wind
  tree::TreeSpec spec;
  TreePipelines pipes;
  tree::Tree grown;
  tree::TreeMesh mesh;
  tree::TreeBounds bounds;
  float mesh_reach = 0.0f;  // the largest offset of a mesh vertex from its skeleton vertex (tree units)
  mutable std::vector<tree::Vec3> bent;  // add_shadow_casters()'s skeleton, kept between frames
  gpu::Buffer vertices, indices, skeleton, parents;
  vk::raii::DescriptorPool pool = nullptr;
  std::vector<SlotResources> slots;
  std::vector<Instance> instances;
  bool level_of_detail = true;

  Impl(const gpu::Context& c, const FrameLoop& loop, const tree::TreeSpec& t)
      : ctx(c), session(loop.session()), spec(t),
        pipes(create_tree_pipelines(c, loop.color_format(), kDepthFormat, kReflectionFormat, kShadowFormat)) {
    const vk::DescriptorPoolSize sizes[] = {
        {.type = vk::DescriptorType::eUniformBuffer, .descriptorCount = kFramesInFlight},
        {.type = vk::DescriptorType::eStorageBuffer, .descriptorCount = 2 * kFramesInFlight}};
    pool = vk::raii::DescriptorPool(
        ctx.device(), vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                   .maxSets = kFramesInFlight, .poolSizeCount = 2,
                                                   .pPoolSizes = sizes});
    for (std::uint32_t k = 0; k < kFramesInFlight; ++k) {
      SlotResources s;
      s.uniforms = gpu::create_buffer(ctx, sizeof(sh::TreeRenderFrame), BU::eUniformBuffer, gpu::MemoryUse::upload,
                                 "tree frame uniforms, slot " + std::to_string(k));
      const vk::DescriptorSetLayout layout = *pipes.set_layout;
      s.set = std::move(vk::raii::DescriptorSets(
          ctx.device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool, .descriptorSetCount = 1,
                                                      .pSetLayouts = &layout})[0]);
      slots.push_back(std::move(s));
    }
    grow();
    const sim::WaterModel& model = loop.model();
    const double land = model.basin.land_height;
    for (std::size_t k = 0; k < spec.positions.size(); ++k) {
      Instance inst;
      const auto& rc = spec.positions[k];
      inst.base = {static_cast<float>(rc[1] * model.spacing), static_cast<float>(land),
                   static_cast<float>(rc[0] * model.spacing), 0.0f};
      instances.push_back(inst);
    }
    rescale();
  }

  // Grows spec's tree at trunk length 1 (tree units; each instance scales it to spec.height) and
  // uploads its mesh and skeleton.
  void grow() {
    grown = tree::grow_tree(tree::TreeParams{.depth = spec.depth, .seed = spec.seed, .trunk_length = 1.0f});
    mesh = tree::build_tree_mesh(grown);
    bounds = tree::tree_bounds(grown, mesh);
    mesh_reach = 0.0f;
    for (const tree::TreeMeshVertex& v : mesh.vertices)
      mesh_reach = std::max(mesh_reach, std::sqrt(v.offset.x * v.offset.x + v.offset.y * v.offset.y + v.offset.z * v.offset.z));
    vertices = gpu::create_buffer(ctx, mesh.vertices.size() * sizeof(tree::TreeMeshVertex), BU::eVertexBuffer | BU::eTransferDst,
                             gpu::MemoryUse::device, "tree mesh vertices");
    gpu::upload(ctx, vertices, std::as_bytes(std::span(mesh.vertices)));
    indices = gpu::create_buffer(ctx, mesh.indices.size() * 4, BU::eIndexBuffer | BU::eTransferDst, gpu::MemoryUse::device,
                            "tree mesh indices");
    gpu::upload(ctx, indices, std::as_bytes(std::span(mesh.indices)));
    skeleton = gpu::create_buffer(ctx, grown.size() * sizeof(tree::TreeVertex), BU::eStorageBuffer | BU::eTransferDst,
                             gpu::MemoryUse::device, "tree skeleton");
    gpu::upload(ctx, skeleton, std::as_bytes(std::span(grown.vertices)));
    parents = gpu::create_buffer(ctx, grown.size() * sizeof(std::int32_t), BU::eStorageBuffer | BU::eTransferDst,
                            gpu::MemoryUse::device, "tree parents");
    gpu::upload(ctx, parents, std::as_bytes(std::span(grown.parents)));
    for (const SlotResources& s : slots) {
      const vk::DescriptorBufferInfo infos[] = {s.uniforms.whole(), skeleton.whole(), parents.whole()};
      const vk::WriteDescriptorSet writes[] = {
          {.dstSet = *s.set, .dstBinding = POND_TREE_BINDING_FRAME, .descriptorCount = 1,
           .descriptorType = vk::DescriptorType::eUniformBuffer, .pBufferInfo = &infos[0]},
          {.dstSet = *s.set, .dstBinding = POND_TREE_BINDING_SKELETON, .descriptorCount = 1,
           .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[1]},
          {.dstSet = *s.set, .dstBinding = POND_TREE_BINDING_PARENTS, .descriptorCount = 1,
           .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[2]}};
      ctx.device().updateDescriptorSets(writes, nullptr);
    }
  }

  void rescale() {
    const float scale = static_cast<float>(spec.height) / mesh.rest_height;
    for (Instance& inst : instances) inst.base.w = scale;
  }

  tree::BendMode bend_mode() const {
    return spec.bend == tree::TreeBend::keep_length ? tree::BendMode::keep_length : tree::BendMode::article;
  }

  // The level of detail at `pixels` per unit length. Without the level of detail `pixels` is
  // infinite: diamonds, every level a tube, no pruning.
  InstanceLod lod_at(float pixels) const {
    InstanceLod l;
    l.thinnest_tube = tree::thinnest_tube_level(pixels, grown.depth);
    l.diamond_leaves = tree::diamond_leaves(pixels, mesh.longest_leaf);
    l.leaves = tree::prune(mesh.leaf_triangles.count / 3, mesh.mean_leaf_area * pixels * pixels, tree::kPrunedLeafArea);
    l.twigs.assign(static_cast<std::size_t>(l.thinnest_tube), {});  // index: level; 0 unused
    for (int level = 1; level < l.thinnest_tube; ++level)
      l.twigs[static_cast<std::size_t>(level)] = tree::prune(
          mesh.lines.level(level).count / 2, 2.0f * tree::tree_tube_radius(grown.depth, level) * pixels, tree::kPrunedTwigPixels);
    return l;
  }

  tree::TreeWindFrame wind_frame(std::size_t k) const { return session.wind().frame(k, bend_mode()); }

  void prepare(const FrameInfo& info) {
    const tree::TreeLodCamera lod_camera = tree::tree_lod_camera(info.view_proj, static_cast<int>(info.extent.height));
    for (std::size_t k = 0; k < instances.size(); ++k) {
      Instance& inst = instances[k];
      inst.frame = wind_frame(k);
      const tree::Sphere s = tree::bent_bounds(bounds, inst.frame);
      const tree::Sphere world{tree::Vec3{inst.base.x, inst.base.y, inst.base.z} + s.centre * inst.base.w, s.radius * inst.base.w};
      const float pixels = level_of_detail ? tree::nearest_pixels_per_unit(lod_camera, world, inst.base.w)
                                           : std::numeric_limits<float>::infinity();
      inst.lod = lod_at(pixels);
      inst.mirrored_lod = lod_at(pixels / static_cast<float>(kReflectionDivisor) * kMirroredLodScale);
    }

    const auto& sun = info.lighting.sun;
    const double sl = std::sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
    sh::TreeRenderFrame f;
    std::memcpy(f.view_proj.m, info.view_proj, sizeof f.view_proj.m);
    f.eye = {info.eye[0], info.eye[1], info.eye[2], 0.0f};
    f.sun = v4({sun[0] / sl, sun[1] / sl, sun[2] / sl});
    f.sky = v4(info.lighting.sky);
    f.bark = kBark;
    f.leaf = kLeaf;
    f.line = kLine;
    f.lod = {lod_camera.pixels_per_unit, static_cast<float>(info.extent.width), static_cast<float>(info.extent.height), 0.0f};
    std::memcpy(slots[info.slot].uniforms.mapped, &f, sizeof f);
    slots[info.slot].uniforms.flush(ctx);
  }

  // What one draw of an instance draws: an index range, and the pruning's scales for the shader.
  struct Part {
    tree::IndexRange range;
    float leaf_scale = 1.0f, twig_scale = 1.0f;
  };
  // Draws each instance's parts of the mesh, `parts(instance, add)` calling add(Part) for each,
  // with `vertex_offset`.
  template <class PartsOf>
  void draw_instances(const vk::raii::CommandBuffer& cmd, const vk::raii::Pipeline& pipe, float pixel_scale,
                      PartsOf parts, std::int32_t vertex_offset = 0) const {
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipe);
    for (const Instance& inst : instances)
      parts(inst, [&](const Part& part) {
        if (part.range.count == 0) return;
        const sh::TreeInstance push{.base = inst.base, .wind = inst.frame,
                                    .pruning = {part.leaf_scale, part.twig_scale, mesh.longest_leaf, pixel_scale}};
        cmd.pushConstants<sh::TreeInstance>(*pipes.layout, vk::ShaderStageFlagBits::eVertex, 0, push);
        cmd.drawIndexed(part.range.count, 1, part.range.first, vertex_offset, 0);
      });
  }

  // The sun's shadow map: the light's projection into the slot's uniforms (host-visible; the slot's
  // frame is still being recorded), each instance's level of detail at the map's texels per unit.
  void prepare_shadow(const FrameInfo& info) {
    const float* m = info.view_proj;  // orthographic: clip x per world unit is its first row's length
    const float texels_per_unit = std::sqrt(m[0] * m[0] + m[4] * m[4] + m[8] * m[8]) * 0.5f *
                                  static_cast<float>(info.extent.width);
    for (Instance& inst : instances)
      inst.shadow_lod = level_of_detail ? lod_at(texels_per_unit * kShadowLodScale * inst.base.w)
                                        : lod_at(std::numeric_limits<float>::infinity());
    const gpu::Buffer& u = slots[info.slot].uniforms;
    std::memcpy(static_cast<std::byte*>(u.mapped) + offsetof(sh::TreeRenderFrame, light_proj), m, sizeof(sh::mat4));
    u.flush(ctx);
  }

  // `lod_of`: which of an instance's levels of detail to draw. `pixel_scale`: 0 for the direct and
  // shadow pipelines, the reflection's pixels per frame pixel for the mirrored ones
  // (TreeInstance::pruning.w).
  void draw(const FrameInfo& info, const TreeMaterialPipelines& pipelines, InstanceLod Instance::*lod_of,
            float pixel_scale) const {
    auto lod = [lod_of](const Instance& i) -> const InstanceLod& { return i.*lod_of; };
    const vk::raii::CommandBuffer& cmd = info.cmd;
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipes.layout, 0, *slots[info.slot].set, nullptr);
    cmd.bindVertexBuffers(0, *vertices.buffer, vk::DeviceSize{0});
    cmd.bindIndexBuffer(*indices.buffer, 0, vk::IndexType::eUint32);
    if (spec.draw == tree::TreeDraw::tubes) {
      draw_instances(cmd, pipelines.tubes, pixel_scale, [&](const Instance& i, auto add) { add({mesh.tubes.at_least(lod(i).thinnest_tube)}); });
      // Each level below the tubes as its (pruned) twig lines: a prefix of the level's shuffled order.
      draw_instances(
          cmd, pipelines.twigs, pixel_scale,
          [&](const Instance& i, auto add) {
            for (int level = 1; level < lod(i).thinnest_tube; ++level) {
              const tree::Pruning& p = lod(i).twigs[static_cast<std::size_t>(level)];
              add({{mesh.lines.level(level).first, 2 * p.count}, 1.0f, p.scale});
            }
          },
          mesh.twig_vertices);
    } else {
      draw_instances(cmd, pipelines.lines, pixel_scale, [&](const Instance&, auto add) { add({mesh.lines.all}); });
    }
    if (spec.leaves)
      draw_instances(cmd, pipelines.leaves, pixel_scale, [&](const Instance& i, auto add) {
        if (lod(i).diamond_leaves)
          add({mesh.leaves});
        else  // a prefix of the shuffled triangles, each grown so the sample covers the crown's area
          add({{mesh.leaf_triangles.first, 3 * lod(i).leaves.count}, std::sqrt(lod(i).leaves.scale), 1.0f});
      });
  }
};

TreeDrawable::TreeDrawable(const gpu::Context& ctx, const FrameLoop& loop, const tree::TreeSpec& tree)
    : impl_(std::make_unique<Impl>(ctx, loop, tree)) {}

// Frames in flight may still read the tree's buffers.
TreeDrawable::~TreeDrawable() {
  if (impl_) impl_->ctx.wait_idle_for_teardown();
}

void TreeDrawable::prepare(const FrameInfo& frame) { impl_->prepare(frame); }
void TreeDrawable::draw(const FrameInfo& frame) { impl_->draw(frame, impl_->pipes.direct, &Instance::lod, 0.0f); }
void TreeDrawable::draw_reflected(const FrameInfo& frame) {
  impl_->draw(frame, impl_->pipes.mirrored, &Instance::mirrored_lod, frame.pixel_scale);
}
// The box around each instance's skeleton as this frame bends it (the CPU's bend, the shader's
// functions), widened by the mesh's reach from it (rings, leaves; pruned far leaves are drawn
// grown, up to twice as far): much tighter than the level of detail's sphere, which holds any
// wind, and what decides how much of the screen samples the shadow map.
void TreeDrawable::add_shadow_casters(std::vector<view::ShadowCaster>& casters) const {
  const Impl& m = *impl_;
  std::vector<tree::Vec3>& bent = m.bent;
  bent.resize(m.grown.size());
  for (const Instance& inst : m.instances) {
    tree::bend_tree(m.grown, inst.frame, bent);
    view::ShadowCaster box{{inst.base.x, inst.base.y, inst.base.z}, {inst.base.x, inst.base.y, inst.base.z}};
    const float base[3] = {inst.base.x, inst.base.y, inst.base.z}, pad = 2.0f * m.mesh_reach * inst.base.w;
    for (const tree::Vec3& p : bent) {
      const float q[3] = {base[0] + p.x * inst.base.w, base[1] + p.y * inst.base.w, base[2] + p.z * inst.base.w};
      for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], q[k] - pad);
        box.hi[k] = std::max(box.hi[k], q[k] + pad);
      }
    }
    casters.push_back(box);
  }
}
void TreeDrawable::draw_shadow(const FrameInfo& frame) {
  impl_->prepare_shadow(frame);
  impl_->draw(frame, impl_->pipes.shadow, &Instance::shadow_lod, 0.0f);
}

void TreeDrawable::regrow(std::uint64_t seed) {
  impl_->ctx.device().waitIdle();  // the buffers being replaced may still be read by frames in flight
  impl_->spec.seed = seed;
  impl_->grow();
  impl_->rescale();
}

void TreeDrawable::set_bend_mode(tree::TreeBend mode) { impl_->spec.bend = mode; }
void TreeDrawable::set_draw_mode(tree::TreeDraw mode) { impl_->spec.draw = mode; }
void TreeDrawable::set_leaves(bool leaves) { impl_->spec.leaves = leaves; }
void TreeDrawable::set_level_of_detail(bool on) { impl_->level_of_detail = on; }

const tree::TreeSpec& TreeDrawable::spec() const { return impl_->spec; }
const tree::Tree& TreeDrawable::tree() const { return impl_->grown; }

std::vector<bool> TreeDrawable::diamond_leaves() const {
  std::vector<bool> out;
  for (const Instance& inst : impl_->instances) out.push_back(inst.lod.diamond_leaves);
  return out;
}

std::vector<int> TreeDrawable::thinnest_tube_levels() const {
  std::vector<int> out;
  for (const Instance& inst : impl_->instances) out.push_back(inst.lod.thinnest_tube);
  return out;
}

std::vector<tree::TreeWindFrame> TreeDrawable::wind_frames() const {
  std::vector<tree::TreeWindFrame> out;
  for (std::size_t k = 0; k < impl_->instances.size(); ++k) out.push_back(impl_->wind_frame(k));
  return out;
}

TreeDrawStats TreeDrawable::stats() const {
  const Impl& m = *impl_;
  return {.instances = m.instances.size(),
          .skeleton_vertices = m.grown.size(),
          .mesh_vertices = m.mesh.vertices.size(),
          .line_segments = m.mesh.lines.all.count / 2,
          .tube_triangles = m.mesh.tubes.all.count / 3,
          .leaf_triangles = m.mesh.leaves.count / 3};
}

}  // namespace pond::render
