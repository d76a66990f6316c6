#include "gpu/compute_pipeline.h"

namespace pond::gpu {

ComputePipeline create_compute_pipeline(const Context& ctx, std::span<const std::uint32_t> spirv,
                                        std::uint32_t storage_buffers, std::uint32_t push_bytes,
                                        std::span<const SpecConstant> constants, const std::string& name) {
  const std::vector<vk::DescriptorType> types(storage_buffers, vk::DescriptorType::eStorageBuffer);
  return create_compute_pipeline(ctx, spirv, types, push_bytes, constants, name);
}

ComputePipeline create_compute_pipeline(const Context& ctx, std::span<const std::uint32_t> spirv,
                                        std::span<const vk::DescriptorType> types, std::uint32_t push_bytes,
                                        std::span<const SpecConstant> constants, const std::string& name) {
  const vk::raii::Device& device = ctx.device();
  ComputePipeline p;
  std::vector<vk::DescriptorSetLayoutBinding> bindings;
  for (std::uint32_t b = 0; b < types.size(); ++b)
    bindings.push_back({.binding = b, .descriptorType = types[b],
                        .descriptorCount = 1, .stageFlags = vk::ShaderStageFlagBits::eCompute});
  p.set_layout = vk::raii::DescriptorSetLayout(
      device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = static_cast<std::uint32_t>(bindings.size()),
                                                .pBindings = bindings.data()});
  const vk::PushConstantRange push{.stageFlags = vk::ShaderStageFlagBits::eCompute, .offset = 0, .size = push_bytes};
  const vk::DescriptorSetLayout set_layout = *p.set_layout;
  p.layout = vk::raii::PipelineLayout(device, vk::PipelineLayoutCreateInfo{
                                                  .setLayoutCount = 1, .pSetLayouts = &set_layout,
                                                  .pushConstantRangeCount = 1, .pPushConstantRanges = &push});
  const vk::raii::ShaderModule module(device, vk::ShaderModuleCreateInfo{.codeSize = spirv.size_bytes(),
                                                                         .pCode = spirv.data()});
  std::vector<vk::SpecializationMapEntry> entries;
  std::vector<std::uint32_t> values;
  for (const SpecConstant& c : constants) {
    entries.push_back({.constantID = c.id, .offset = static_cast<std::uint32_t>(values.size() * 4), .size = 4});
    values.push_back(c.value);
  }
  const vk::SpecializationInfo spec{.mapEntryCount = static_cast<std::uint32_t>(entries.size()),
                                    .pMapEntries = entries.data(),
                                    .dataSize = values.size() * 4,
                                    .pData = values.data()};
  const vk::ComputePipelineCreateInfo info{
      .stage = {.stage = vk::ShaderStageFlagBits::eCompute, .module = *module, .pName = "main",
                .pSpecializationInfo = constants.empty() ? nullptr : &spec},
      .layout = *p.layout};
  p.pipeline = vk::raii::Pipeline(device, nullptr, info);
  ctx.name(module, name);
  ctx.name(p.set_layout, name + " set layout");
  ctx.name(p.layout, name + " layout");
  ctx.name(p.pipeline, name);
  return p;
}

}  // namespace pond::gpu
