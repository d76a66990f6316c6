// Pins the denormal and signed-zero policy of src/gpu/float_policy.h on the device: each case is
// one correctly rounded operation, computed by the probe shader and by the CPU, compared by bits.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu_fixture.h"
#include "shared/exact_math.h"

namespace pond::test {
namespace {
#include "float_probe_comp.spv.h"

struct Operands {
  float a, b;
};

std::vector<float> run_probe(const gpu::Context& ctx, const std::vector<Operands>& ops) {
  using BU = vk::BufferUsageFlagBits;
  const gpu::ComputePipeline pipe =
      gpu::create_compute_pipeline(ctx, pond_spirv_float_probe_comp, 2, 4, {}, "float probe");
  const gpu::Buffer in = gpu::create_buffer(ctx, ops.size() * 8, BU::eStorageBuffer | BU::eTransferDst,
                                            gpu::MemoryUse::device, "probe operands");
  const gpu::Buffer out = gpu::create_buffer(ctx, ops.size() * 16, BU::eStorageBuffer | BU::eTransferSrc,
                                             gpu::MemoryUse::device, "probe results");
  const gpu::Buffer back = gpu::create_buffer(ctx, ops.size() * 16, BU::eTransferDst, gpu::MemoryUse::readback,
                                              "probe readback");
  gpu::upload(ctx, in, std::as_bytes(std::span(ops)));
  const vk::DescriptorPoolSize size{.type = vk::DescriptorType::eStorageBuffer, .descriptorCount = 2};
  const vk::raii::DescriptorPool pool(ctx.device(), vk::DescriptorPoolCreateInfo{
      .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, .maxSets = 1, .poolSizeCount = 1,
      .pPoolSizes = &size});
  const vk::DescriptorSetLayout layout = *pipe.set_layout;
  vk::raii::DescriptorSets sets(ctx.device(), vk::DescriptorSetAllocateInfo{
      .descriptorPool = *pool, .descriptorSetCount = 1, .pSetLayouts = &layout});
  const vk::DescriptorBufferInfo infos[2] = {in.whole(), out.whole()};
  const vk::WriteDescriptorSet writes[2] = {
      {.dstSet = *sets[0], .dstBinding = 0, .descriptorCount = 1,
       .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[0]},
      {.dstSet = *sets[0], .dstBinding = 1, .descriptorCount = 1,
       .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[1]}};
  ctx.device().updateDescriptorSets(writes, nullptr);
  const auto count = static_cast<std::uint32_t>(ops.size());
  ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    using S = vk::PipelineStageFlagBits2;
    using A = vk::AccessFlagBits2;
    const vk::MemoryBarrier2 upload_done{.srcStageMask = S::eTransfer, .srcAccessMask = A::eTransferWrite,
                                         .dstStageMask = S::eComputeShader, .dstAccessMask = A::eShaderRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &upload_done});
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipe.pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipe.layout, 0, *sets[0], nullptr);
    cmd.pushConstants<std::uint32_t>(*pipe.layout, vk::ShaderStageFlagBits::eCompute, 0, count);
    cmd.dispatch(gpu::group_count(count, 8), 1, 1);
    const vk::MemoryBarrier2 to_copy{.srcStageMask = S::eComputeShader, .srcAccessMask = A::eShaderWrite,
                                     .dstStageMask = S::eTransfer, .dstAccessMask = A::eTransferRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_copy});
    cmd.copyBuffer(*out.buffer, *back.buffer, vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = out.size});
    const vk::MemoryBarrier2 to_host{.srcStageMask = S::eTransfer, .srcAccessMask = A::eTransferWrite,
                                     .dstStageMask = S::eHost, .dstAccessMask = A::eHostRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
  });
  back.invalidate(ctx);
  std::vector<float> results(ops.size() * 4);
  std::memcpy(results.data(), back.mapped, results.size() * sizeof(float));
  return results;
}

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

using FloatPolicyTest = GpuTest;

TEST_F(FloatPolicyTest, DenormalsAndSignedZerosFollowIeeeAsOnTheCpu) {
  const float tiny = std::numeric_limits<float>::denorm_min();
  const float min_normal = std::numeric_limits<float>::min();
  const std::vector<Operands> ops = {
      {1e-20f, 1e-20f},                 // a normal product that is denormal (no flush of results)
      {3e-39f, 1.0f},                   // a denormal operand (no flush of inputs)
      {3e-39f, 2e-39f},                 // denormal + denormal, denormal - denormal
      {min_normal, min_normal * 0.5f},  // difference of normals that is denormal
      {tiny, -tiny},                    // the smallest denormal
      {-0.0f, -0.0f},                   // -0 + -0 = -0, -0 - -0 = +0, -0 * -0 = +0
      {-0.0f, 0.0f},                    // -0 + +0 = +0, -0 - +0 = -0, -0 * +0 = -0
      {0.0f, -5.0f},                    // +0 * -5 = -0
      {-0.0f, 3.0f},                    // -0 + 3 = 3
      {2.5f, 2.5f},                     // x - x = +0
      {1.0f, 1e-45f},                   // 1 + denorm_min = 1 (rounding, not flushing)
  };
  const std::vector<float> gpu = run_probe(ctx(), ops);
  int mismatches = 0;
  for (std::size_t k = 0; k < ops.size(); ++k) {
    const float a = ops[k].a, b = ops[k].b;
    const float cpu[4] = {a + b, a - b, a * b, shared::rsqrt_exact(std::fabs(a), shared::kRsqrtStepsExact)};
    for (int r = 0; r < 4; ++r) {
      if (bits(cpu[r]) == bits(gpu[k * 4 + r])) continue;
      ++mismatches;
      ADD_FAILURE() << "case " << k << " op " << "+-*r"[r] << ": a=" << a << " b=" << b << " cpu 0x" << std::hex
                    << bits(cpu[r]) << " gpu 0x" << bits(gpu[k * 4 + r]) << std::dec;
    }
  }
  EXPECT_EQ(mismatches, 0);
  // And the cases really are what they claim: results in the denormal range, zeros of both signs.
  EXPECT_EQ(std::fpclassify(gpu[0 * 4 + 2]), FP_SUBNORMAL);
  EXPECT_EQ(std::fpclassify(gpu[2 * 4 + 0]), FP_SUBNORMAL);
  EXPECT_EQ(bits(gpu[5 * 4 + 0]), 0x80000000u);
  EXPECT_EQ(bits(gpu[6 * 4 + 0]), 0x00000000u);
  EXPECT_EQ(bits(gpu[7 * 4 + 2]), 0x80000000u);
}

}  // namespace
}  // namespace pond::test
