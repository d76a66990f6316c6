#pragma once
// A compute pipeline with its own descriptor-set layout (storage buffers at bindings 0..n-1) and
// push-constant range: the shape of every water pass.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gpu/context.h"

namespace pond::gpu {

struct SpecConstant {
  std::uint32_t id;
  std::uint32_t value;  // bool and int constants are both 32-bit words
};

struct ComputePipeline {
  vk::raii::DescriptorSetLayout set_layout = nullptr;
  vk::raii::PipelineLayout layout = nullptr;
  vk::raii::Pipeline pipeline = nullptr;
};

ComputePipeline create_compute_pipeline(const Context& ctx, std::span<const std::uint32_t> spirv,
                                        std::uint32_t storage_buffers, std::uint32_t push_bytes,
                                        std::span<const SpecConstant> constants, const std::string& name);
// The same with any descriptor type at each binding (bindings 0..n-1 in the order given).
ComputePipeline create_compute_pipeline(const Context& ctx, std::span<const std::uint32_t> spirv,
                                        std::span<const vk::DescriptorType> bindings, std::uint32_t push_bytes,
                                        std::span<const SpecConstant> constants, const std::string& name);

// Group count for `threads` invocations of a shader whose local size is `local` along that axis:
// any size, not only multiples of the workgroup (the shader bounds-checks).
constexpr std::uint32_t group_count(std::uint32_t threads, std::uint32_t local) {
  return (threads + local - 1) / local;
}

}  // namespace pond::gpu
