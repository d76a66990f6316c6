#include "render/reflection_pass.h"

#include <algorithm>

namespace pond::render {

vk::Extent2D reflection_extent(vk::Extent2D frame) {
  return {std::max(1u, (frame.width + kReflectionDivisor - 1) / kReflectionDivisor),
          std::max(1u, (frame.height + kReflectionDivisor - 1) / kReflectionDivisor)};
}

vk::raii::Sampler create_reflection_sampler(const gpu::Context& ctx) {
  using AM = vk::SamplerAddressMode;
  return vk::raii::Sampler(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eNearest, .minFilter = vk::Filter::eNearest,
                                                               .mipmapMode = vk::SamplerMipmapMode::eNearest,
                                                               .addressModeU = AM::eClampToEdge, .addressModeV = AM::eClampToEdge,
                                                               .addressModeW = AM::eClampToEdge, .maxLod = 0.0f});
}

}  // namespace pond::render
