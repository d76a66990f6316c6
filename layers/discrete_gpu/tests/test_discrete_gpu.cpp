// VK_LAYER_POND_discrete_gpu seen from an application: what the device reports, and that the
// memory really behaves as non-coherent memory behind a discrete GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include "layer_device.h"

namespace pond::layer_test {
namespace {

using MP = vk::MemoryPropertyFlagBits;
constexpr vk::DeviceSize kSize = 4096;
constexpr vk::DeviceSize kAtom = 256;  // the presented nonCoherentAtomSize
constexpr std::uint32_t kPoisonWord = 0xFFFFFFFFu;  // what a mapping reads before an invalidate

// Sets (or, with nullptr, unsets) an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    value ? ::setenv(name, value, 1) : ::unsetenv(name);
  }
  ~ScopedEnv() { old_ ? ::setenv(name_, old_->c_str(), 1) : ::unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

std::byte pattern_byte(std::size_t i) { return static_cast<std::byte>((i * 131 + 7) & 0xFF); }

void write_pattern(std::byte* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) p[i] = pattern_byte(i);
}

bool has_pattern(const std::byte* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (p[i] != pattern_byte(i)) return false;
  return true;
}

bool all_words(const std::byte* p, std::size_t n, std::uint32_t word) {
  for (std::size_t i = 0; i + 4 <= n; i += 4) {
    std::uint32_t w;
    std::memcpy(&w, p + i, 4);
    if (w != word) return false;
  }
  return true;
}

bool mentions(const std::vector<std::string>& messages, const std::string& vuid) {
  return std::any_of(messages.begin(), messages.end(),
                     [&](const std::string& m) { return m.find(vuid) != std::string::npos; });
}

TEST(DiscreteGpuLayer, PresentsADiscreteGpuWithDesktopLimits) {
  LayerDevice gpu;
  const vk::PhysicalDeviceProperties props = gpu.physical().getProperties();
  EXPECT_EQ(props.deviceType, vk::PhysicalDeviceType::eDiscreteGpu);
  EXPECT_EQ(gpu.physical().getProperties2().properties.deviceType, vk::PhysicalDeviceType::eDiscreteGpu);
  EXPECT_EQ(props.limits.nonCoherentAtomSize, 256u);
  EXPECT_EQ(props.limits.maxComputeWorkGroupSize[2], 64u);
  EXPECT_LE(props.limits.maxMemoryAllocationCount, 4096u);
  EXPECT_LE(props.limits.maxSamplerAllocationCount, 4000u);
  const auto chain = gpu.physical().getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceVulkan11Properties,
                                                   vk::PhysicalDeviceSubgroupProperties>();
  EXPECT_EQ(chain.get<vk::PhysicalDeviceVulkan11Properties>().subgroupSize, 32u);
  EXPECT_EQ(chain.get<vk::PhysicalDeviceSubgroupProperties>().subgroupSize, 32u);
  EXPECT_TRUE(gpu.take_messages().empty());
}

TEST(DiscreteGpuLayer, NoMemoryTypeIsBothDeviceLocalAndHostVisible) {
  LayerDevice gpu;
  const auto props = gpu.physical().getMemoryProperties2().memoryProperties;
  bool device_local = false, host_visible = false;
  for (std::uint32_t t = 0; t < props.memoryTypeCount; ++t) {
    const vk::MemoryPropertyFlags f = props.memoryTypes[t].propertyFlags;
    EXPECT_FALSE((f & MP::eDeviceLocal) && (f & MP::eHostVisible)) << "type " << t << ": " << vk::to_string(f);
    device_local = device_local || bool(f & MP::eDeviceLocal);
    host_visible = host_visible || bool(f & MP::eHostVisible);
    // Host memory is on a heap of its own, as system memory is on a discrete GPU.
    if (f & MP::eHostVisible) {
      EXPECT_FALSE(props.memoryHeaps[props.memoryTypes[t].heapIndex].flags & vk::MemoryHeapFlagBits::eDeviceLocal);
    }
  }
  EXPECT_TRUE(device_local);
  EXPECT_TRUE(host_visible);
}

TEST(DiscreteGpuLayer, HostVisibleMemoryIsNotCoherent) {
  LayerDevice gpu;
  const auto props = gpu.physical().getMemoryProperties();
  for (std::uint32_t t = 0; t < props.memoryTypeCount; ++t) {
    const vk::MemoryPropertyFlags f = props.memoryTypes[t].propertyFlags;
    if (f & MP::eHostVisible) {
      EXPECT_FALSE(f & MP::eHostCoherent) << "type " << t << ": " << vk::to_string(f);
    }
  }
}

TEST(DiscreteGpuLayer, BuffersMayLiveInEitherKindOfMemory) {
  LayerDevice gpu;
  const vk::raii::Buffer buffer(gpu.device(), vk::BufferCreateInfo{.size = kSize,
                                                                   .usage = vk::BufferUsageFlagBits::eStorageBuffer});
  const std::uint32_t bits = buffer.getMemoryRequirements().memoryTypeBits;
  EXPECT_NO_THROW(gpu.memory_type(bits, MP::eDeviceLocal));
  EXPECT_NO_THROW(gpu.memory_type(bits, MP::eHostVisible));
  const auto props = gpu.physical().getMemoryProperties();
  EXPECT_EQ(bits >> props.memoryTypeCount, 0u) << "a bit names a type that does not exist";
}

TEST(DiscreteGpuLayer, HidesShaderInt64) {
  LayerDevice gpu;
  EXPECT_FALSE(gpu.physical().getFeatures().shaderInt64);
  const auto chain = gpu.physical().getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan12Features>();
  EXPECT_FALSE(chain.get<vk::PhysicalDeviceFeatures2>().features.shaderInt64);
  EXPECT_FALSE(chain.get<vk::PhysicalDeviceVulkan12Features>().shaderBufferInt64Atomics);
  EXPECT_FALSE(chain.get<vk::PhysicalDeviceVulkan12Features>().shaderSharedInt64Atomics);
}

TEST(DiscreteGpuLayer, RefusesADeviceThatAsksForShaderInt64) {
  LayerDevice gpu;
  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, nullptr, 0, 0, 1, &priority};
  VkPhysicalDeviceFeatures features{};
  features.shaderInt64 = VK_TRUE;
  const VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, nullptr, 0, 1, &queue, 0, nullptr, 0, nullptr,
                                &features};
  VkDevice device = VK_NULL_HANDLE;
  EXPECT_EQ(gpu.physical().getDispatcher()->vkCreateDevice(*gpu.physical(), &info, nullptr, &device),
            VK_ERROR_FEATURE_NOT_PRESENT);
  gpu.take_messages();  // validation, above the layer, also reports the unsupported feature
}

// POND_DISCRETE_GPU_DENORM_PRESERVE chooses what the device advertises (default: preserve).
void expect_denorm_preserve(bool expected) {
  LayerDevice gpu;
  const auto v12 = gpu.physical().getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceVulkan12Properties>();
  EXPECT_EQ(bool(v12.get<vk::PhysicalDeviceVulkan12Properties>().shaderDenormPreserveFloat32), expected);
  const auto controls =
      gpu.physical().getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceFloatControlsProperties>();
  EXPECT_EQ(bool(controls.get<vk::PhysicalDeviceFloatControlsProperties>().shaderDenormPreserveFloat32), expected);
}

TEST(DiscreteGpuLayer, DenormPreserveIsAdvertisedByDefault) {
  const ScopedEnv unset("POND_DISCRETE_GPU_DENORM_PRESERVE", nullptr);
  expect_denorm_preserve(true);
  const ScopedEnv one("POND_DISCRETE_GPU_DENORM_PRESERVE", "1");
  expect_denorm_preserve(true);
}

TEST(DiscreteGpuLayer, DenormSettingZeroWithdrawsPreserve) {
  const ScopedEnv zero("POND_DISCRETE_GPU_DENORM_PRESERVE", "0");
  expect_denorm_preserve(false);
}

TEST(DiscreteGpuLayer, DeviceLocalMemoryCannotBeMapped) {
  LayerDevice gpu;
  const vk::raii::DeviceMemory memory(
      gpu.device(), vk::MemoryAllocateInfo{.allocationSize = kSize,
                                           .memoryTypeIndex = gpu.memory_type(~0u, MP::eDeviceLocal, MP::eHostVisible)});
  void* data = nullptr;
  EXPECT_EQ(gpu.device().getDispatcher()->vkMapMemory(*gpu.device(), *memory, 0, VK_WHOLE_SIZE, 0, &data),
            VK_ERROR_MEMORY_MAP_FAILED);
  // Validation sits above the layer, so it judges the presented memory type, not lavapipe's.
  EXPECT_TRUE(mentions(gpu.take_messages(), "VUID-vkMapMemory-memory-00682"))
      << "validation did not see the presented memory type: is it listed below the layer?";
}

// The loader stacks the environment's layers above those the application enables: validation
// enabled by the application checks lavapipe as it is, and misses what only the layer forbids.
TEST(DiscreteGpuLayer, ValidationEnabledByTheApplicationSitsBelowTheLayer) {
  const ScopedEnv only_layer("VK_INSTANCE_LAYERS", "VK_LAYER_POND_discrete_gpu");
  LayerDevice gpu({"VK_LAYER_KHRONOS_validation"});
  EXPECT_EQ(gpu.physical().getProperties().deviceType, vk::PhysicalDeviceType::eDiscreteGpu);
  const vk::raii::DeviceMemory memory(
      gpu.device(), vk::MemoryAllocateInfo{.allocationSize = kSize,
                                           .memoryTypeIndex = gpu.memory_type(~0u, MP::eDeviceLocal, MP::eHostVisible)});
  void* data = nullptr;
  EXPECT_EQ(gpu.device().getDispatcher()->vkMapMemory(*gpu.device(), *memory, 0, VK_WHOLE_SIZE, 0, &data),
            VK_ERROR_MEMORY_MAP_FAILED);
  const auto messages = gpu.take_messages();
  EXPECT_TRUE(messages.empty()) << joined(messages);
}

TEST(DiscreteGpuLayer, HostWritesReachTheDeviceOnlyWhenFlushed) {
  LayerDevice gpu;
  HostBuffer src = gpu.host_buffer(kSize), dst = gpu.host_buffer(kSize);
  write_pattern(src.mapped, kSize);
  const auto copy_and_read = [&] {
    gpu.submit([&](const vk::raii::CommandBuffer& cmd) {
      cmd.copyBuffer(*src.buffer, *dst.buffer, vk::BufferCopy{.size = kSize});
    });
    EXPECT_EQ(gpu.invalidate(dst.memory, 0, VK_WHOLE_SIZE), VK_SUCCESS);
  };
  copy_and_read();
  EXPECT_FALSE(has_pattern(dst.mapped, kSize)) << "the GPU saw host writes that were never flushed";
  ASSERT_EQ(gpu.flush(src.memory, 0, VK_WHOLE_SIZE), VK_SUCCESS);
  copy_and_read();
  EXPECT_TRUE(has_pattern(dst.mapped, kSize)) << "the GPU did not see flushed host writes";
  const auto messages = gpu.take_messages();
  EXPECT_TRUE(messages.empty()) << joined(messages);
}

TEST(DiscreteGpuLayer, DeviceWritesReachTheHostOnlyWhenInvalidated) {
  LayerDevice gpu;
  HostBuffer b = gpu.host_buffer(kSize);
  EXPECT_TRUE(all_words(b.mapped, kSize, kPoisonWord)) << "a fresh mapping shows the poison until invalidated";
  const auto fill = [&](std::uint32_t word) {
    gpu.submit([&](const vk::raii::CommandBuffer& cmd) { cmd.fillBuffer(*b.buffer, 0, VK_WHOLE_SIZE, word); });
  };
  fill(0x2A2A2A2A);
  EXPECT_TRUE(all_words(b.mapped, kSize, kPoisonWord)) << "GPU writes reached the host without an invalidate";
  ASSERT_EQ(gpu.invalidate(b.memory, 0, VK_WHOLE_SIZE), VK_SUCCESS);
  EXPECT_TRUE(all_words(b.mapped, kSize, 0x2A2A2A2A));
  fill(0x17171717);
  EXPECT_TRUE(all_words(b.mapped, kSize, 0x2A2A2A2A)) << "the host copy changed without an invalidate";
  ASSERT_EQ(gpu.invalidate(b.memory, 0, VK_WHOLE_SIZE), VK_SUCCESS);
  EXPECT_TRUE(all_words(b.mapped, kSize, 0x17171717));
  const auto messages = gpu.take_messages();
  EXPECT_TRUE(messages.empty()) << joined(messages);
}

TEST(DiscreteGpuLayer, UnmapWithoutFlushLosesTheWrites) {
  LayerDevice gpu;
  HostBuffer b = gpu.host_buffer(kSize);
  gpu.submit([&](const vk::raii::CommandBuffer& cmd) { cmd.fillBuffer(*b.buffer, 0, VK_WHOLE_SIZE, 0u); });
  write_pattern(b.mapped, kSize);
  b.memory.unmapMemory();
  b.mapped = static_cast<std::byte*>(b.memory.mapMemory(0, VK_WHOLE_SIZE));
  ASSERT_EQ(gpu.invalidate(b.memory, 0, VK_WHOLE_SIZE), VK_SUCCESS);
  EXPECT_TRUE(all_words(b.mapped, kSize, 0u)) << "unmapping flushed the writes";
  const auto messages = gpu.take_messages();
  EXPECT_TRUE(messages.empty()) << joined(messages);
}

TEST(DiscreteGpuLayer, MisalignedRangesAreRefused) {
  LayerDevice gpu;
  constexpr vk::DeviceSize kOdd = 1000;  // not a multiple of the 256-byte atom
  vk::raii::DeviceMemory memory(gpu.device(), vk::MemoryAllocateInfo{
                                                  .allocationSize = kOdd,
                                                  .memoryTypeIndex = gpu.memory_type(~0u, MP::eHostVisible)});
  ASSERT_NE(memory.mapMemory(0, VK_WHOLE_SIZE), nullptr);
  EXPECT_EQ(gpu.flush(memory, 64, 256), VK_ERROR_UNKNOWN);    // offset off the atom
  EXPECT_EQ(gpu.flush(memory, 0, 100), VK_ERROR_UNKNOWN);     // size off the atom, short of the end
  EXPECT_EQ(gpu.invalidate(memory, 64, VK_WHOLE_SIZE), VK_ERROR_UNKNOWN);
  const auto refused = gpu.take_messages();
  EXPECT_TRUE(mentions(refused, "VUID-VkMappedMemoryRange-offset-00687")) << joined(refused);
  EXPECT_TRUE(mentions(refused, "VUID-VkMappedMemoryRange-size-01390")) << joined(refused);

  EXPECT_EQ(gpu.flush(memory, 0, 256), VK_SUCCESS);
  EXPECT_EQ(gpu.flush(memory, 256, kOdd - 256), VK_SUCCESS);  // ends at the end of the allocation
  EXPECT_EQ(gpu.flush(memory, 512, VK_WHOLE_SIZE), VK_SUCCESS);
  EXPECT_EQ(gpu.invalidate(memory, 0, VK_WHOLE_SIZE), VK_SUCCESS);
  const auto messages = gpu.take_messages();
  EXPECT_TRUE(messages.empty()) << joined(messages);
}

}  // namespace
}  // namespace pond::layer_test

namespace pond::layer_test {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Known calls give known counts, written when the device is destroyed: each submission call; each
// host wait of the four kinds, and nothing for polling a fence or signalling from the host; the
// bytes of each flushed or invalidated range, VK_WHOLE_SIZE up to the end of the mapping; each
// allocation.
TEST(DiscreteGpuLayer, CountsSubmissionsHostWaitsAndBytes) {
  const std::string path = std::string(POND_TEST_XDG_RUNTIME_DIR) + "/counters.json";
  std::remove(path.c_str());
  const ScopedEnv stats("POND_DISCRETE_GPU_STATS", path.c_str());
  vk::DeviceSize whole = 0;
  {
    std::optional<LayerDevice> gpu(std::in_place);
    {
      HostBuffer b = gpu->host_buffer(kSize);
      whole = b.allocation_size;
      ASSERT_GE(whole, 2 * kAtom);
      gpu->submit([&](const vk::raii::CommandBuffer& cmd) { cmd.fillBuffer(*b.buffer, 0, VK_WHOLE_SIZE, 1u); });  // 1 submit, 1 wait
      gpu->submit([&](const vk::raii::CommandBuffer& cmd) { cmd.fillBuffer(*b.buffer, 0, VK_WHOLE_SIZE, 2u); });  // 1 submit, 1 wait
      EXPECT_EQ(gpu->flush(b.memory, 0, kAtom), VK_SUCCESS);                  // kAtom bytes flushed
      EXPECT_EQ(gpu->flush(b.memory, kAtom, VK_WHOLE_SIZE), VK_SUCCESS);      // whole - kAtom
      EXPECT_EQ(gpu->invalidate(b.memory, 0, VK_WHOLE_SIZE), VK_SUCCESS);     // whole invalidated
      EXPECT_EQ(gpu->invalidate(b.memory, kAtom, 2 * kAtom), VK_SUCCESS);     // 2 kAtom more
    }
    const vk::raii::Device& device = gpu->device();
    const vk::raii::Fence fence(device, vk::FenceCreateInfo{});
    gpu->queue().submit(nullptr, *fence);  // 1 submit (no batches)
    while (fence.getStatus() == vk::Result::eNotReady) {  // polling: no wait
    }
    EXPECT_EQ(device.waitForFences(*fence, VK_TRUE, UINT64_MAX), vk::Result::eSuccess);  // 1 wait
    const vk::SemaphoreTypeCreateInfo timeline{.semaphoreType = vk::SemaphoreType::eTimeline, .initialValue = 0};
    const vk::raii::Semaphore semaphore(device, vk::SemaphoreCreateInfo{.pNext = &timeline});
    device.signalSemaphore(vk::SemaphoreSignalInfo{.semaphore = *semaphore, .value = 1});  // not a wait
    const std::uint64_t value = 1;
    EXPECT_EQ(device.waitSemaphores(vk::SemaphoreWaitInfo{.semaphoreCount = 1, .pSemaphores = &*semaphore,
                                                          .pValues = &value},
                                    UINT64_MAX),
              vk::Result::eSuccess);  // 1 wait
    device.waitIdle();                // 1 wait
    const auto messages = gpu->take_messages();
    EXPECT_TRUE(messages.empty()) << joined(messages);
  }  // ~LayerDevice: vkDeviceWaitIdle (1 wait), then vkDestroyDevice writes the file
  char expected[256];
  std::snprintf(expected, sizeof expected,
                "{\"submits\": 3, \"host_waits\": 6, \"bytes_flushed\": %llu, \"bytes_invalidated\": %llu, "
                "\"allocations\": 1}\n",
                static_cast<unsigned long long>(whole), static_cast<unsigned long long>(whole + 2 * kAtom));
  EXPECT_EQ(read_file(path), expected);
}

}  // namespace
}  // namespace pond::layer_test
