#include "gpu/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/errors.h"
#include "gpu/device_choice.h"

namespace pond::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// vk::raii::Context loads libvulkan.so.1 and throws a bare std::runtime_error without it.
vk::raii::Context load_vulkan() {
  try {
    return vk::raii::Context();
  } catch (const std::exception& e) {
    throw RuntimeError(std::string("Vulkan is not available (") + e.what() +
                       "); the CPU solvers (--solver scalar|sse|avx2) do not need it");
  }
}

bool has_extension(const std::vector<vk::ExtensionProperties>& list, const char* name) {
  return std::any_of(list.begin(), list.end(),
                     [&](const vk::ExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// With a window the one queue must also present: keep the chosen family when it can, else take
// another compute + graphics family that can.
std::uint32_t present_family(const vk::raii::PhysicalDevice& physical, vk::SurfaceKHR surface,
                             std::uint32_t chosen, const std::string& device_name) {
  if (physical.getSurfaceSupportKHR(chosen, surface)) return chosen;
  const auto families = physical.getQueueFamilyProperties();
  const auto both = vk::QueueFlagBits::eCompute | vk::QueueFlagBits::eGraphics;
  for (std::uint32_t f = 0; f < families.size(); ++f)
    if ((families[f].queueFlags & both) == both && physical.getSurfaceSupportKHR(f, surface)) return f;
  throw RuntimeError("the Vulkan device " + device_name + " cannot present to the window (choose another with --device)");
}

}  // namespace

Context::Context(const ContextOptions& options, const WindowSurface& window)
    : log_(std::make_unique<ValidationLog>()), loader_(load_vulkan()) {
  std::vector<const char*> layers, extensions;
  const auto available = loader_.enumerateInstanceExtensionProperties();
  debug_utils_ = has_extension(available, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (options.validation) {
    const auto layer_list = loader_.enumerateInstanceLayerProperties();
    const bool have_layer = std::any_of(layer_list.begin(), layer_list.end(), [](const vk::LayerProperties& l) {
      return std::strcmp(l.layerName, kValidationLayer) == 0;
    });
    if (!have_layer) throw RuntimeError(std::string("validation requested but ") + kValidationLayer + " is not installed");
    layers.push_back(kValidationLayer);
    const auto layer_ext = loader_.enumerateInstanceExtensionProperties(std::string(kValidationLayer));
    if (!has_extension(layer_ext, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME))
      throw RuntimeError("the validation layer lacks VK_EXT_validation_features (synchronization validation)");
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    debug_utils_ = debug_utils_ || has_extension(layer_ext, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (!debug_utils_) throw RuntimeError("validation requested but VK_EXT_debug_utils is not available");
  }
  if (debug_utils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  for (const std::string& e : window.instance_extensions) {
    if (!has_extension(available, e.c_str())) throw RuntimeError("the Vulkan instance lacks " + e + ", needed by the window");
    extensions.push_back(e.c_str());
  }

  const vk::ApplicationInfo app{.pApplicationName = "pond", .applicationVersion = 1,
                                .pEngineName = "pond", .engineVersion = 1,
                                .apiVersion = VK_API_VERSION_1_3};
  // Synchronization validation checks the barriers between the substeps' dispatches.
  const vk::ValidationFeatureEnableEXT enables[] = {vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
  vk::DebugUtilsMessengerCreateInfoEXT messenger_info = log_->messenger_info();
  vk::ValidationFeaturesEXT features{.pNext = &messenger_info, .enabledValidationFeatureCount = 1,
                                     .pEnabledValidationFeatures = enables};
  const vk::InstanceCreateInfo info{
      .pNext = options.validation ? static_cast<const void*>(&features) : nullptr,
      .pApplicationInfo = &app,
      .enabledLayerCount = static_cast<std::uint32_t>(layers.size()),
      .ppEnabledLayerNames = layers.data(),
      .enabledExtensionCount = static_cast<std::uint32_t>(extensions.size()),
      .ppEnabledExtensionNames = extensions.data()};
  try {
    instance_ = vk::raii::Instance(loader_, info);
  } catch (const vk::SystemError& e) {
    throw RuntimeError(std::string("cannot create a Vulkan 1.3 instance: ") + e.what());
  }
  if (options.validation) messenger_.emplace(instance_, messenger_info);
  if (window.make_surface) surface_ = vk::raii::SurfaceKHR(instance_, window.make_surface(*instance_));

  // No name given: POND_DEVICE, the one variable that steers every command and the test suite.
  const char* env_device = std::getenv("POND_DEVICE");
  const bool from_env = options.device.empty() && env_device;
  DeviceChoice choice = choose_device(instance_, from_env ? env_device : options.device,
                                      from_env ? "POND_DEVICE=" : "--device ");
  physical_ = std::move(choice.physical);
  family_ = choice.compute_family;
  device_name_ = std::move(choice.name);
  std::vector<const char*> device_extensions;
  if (*surface_) {
    family_ = present_family(physical_, *surface_, family_, device_name_);
    device_extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  }

  const float priority = 1.0f;
  const vk::DeviceQueueCreateInfo queue_info{.queueFamilyIndex = family_, .queueCount = 1,
                                             .pQueuePriorities = &priority};
  // Both are required by Vulkan 1.3: synchronization2 for the barriers, maintenance4 because
  // glslang's SPIR-V 1.6 declares workgroup sizes with LocalSizeId.
  // dynamicRendering: the renderer draws into offscreen and swapchain images without render passes.
  // fillModeNonSolid (where supported): the LOD wireframe overlay. shaderInt64 (where supported):
  // the water step's 64-bit stores.
  vk::PhysicalDeviceVulkan13Features features13{.synchronization2 = VK_TRUE, .dynamicRendering = VK_TRUE,
                                                .maintenance4 = VK_TRUE};
  const vk::PhysicalDeviceFeatures supported = physical_.getFeatures();
  int64_ = options.int64 && supported.shaderInt64 == VK_TRUE;
  const auto properties = physical_.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceVulkan11Properties,
                                                   vk::PhysicalDeviceVulkan12Properties>();
  const auto& v12 = properties.get<vk::PhysicalDeviceVulkan12Properties>();
  subgroup_size_ = std::max(1u, properties.get<vk::PhysicalDeviceVulkan11Properties>().subgroupSize);
  denorm_preserve_ = v12.shaderDenormPreserveFloat32 == VK_TRUE;
  signed_zero_preserve_ = v12.shaderSignedZeroInfNanPreserveFloat32 == VK_TRUE;
  driver_id_ = v12.driverID;
  driver_ = std::string(v12.driverName.data()) + " " + v12.driverInfo.data();
  api_version_ = properties.get<vk::PhysicalDeviceProperties2>().properties.apiVersion;
  non_coherent_atom_ = std::max<vk::DeviceSize>(1, properties.get<vk::PhysicalDeviceProperties2>().properties.limits.nonCoherentAtomSize);
  const vk::PhysicalDeviceFeatures core_features{.fillModeNonSolid = supported.fillModeNonSolid,
                                                 .shaderInt64 = int64_ ? VK_TRUE : VK_FALSE};
  const vk::DeviceCreateInfo device_info{.pNext = &features13, .queueCreateInfoCount = 1,
                                         .pQueueCreateInfos = &queue_info,
                                         .enabledExtensionCount = static_cast<std::uint32_t>(device_extensions.size()),
                                         .ppEnabledExtensionNames = device_extensions.data(), .pEnabledFeatures = &core_features};
  try {
    device_ = vk::raii::Device(physical_, device_info);
  } catch (const vk::SystemError& e) {
    throw RuntimeError("cannot create a Vulkan device on " + device_name_ + ": " + e.what());
  }
  queue_ = vk::raii::Queue(device_, family_, 0);
  pool_ = vk::raii::CommandPool(device_, vk::CommandPoolCreateInfo{
                                             .flags = vk::CommandPoolCreateFlagBits::eTransient,
                                             .queueFamilyIndex = family_});
  name(queue_, "pond compute queue");
  name(pool_, "pond command pool");
}

Context::~Context() { wait_idle_for_teardown(); }

void Context::wait_idle_for_teardown() const noexcept {
  if (!*device_) return;
  try {
    device_.waitIdle();
  } catch (const vk::SystemError&) {  // lost: nothing runs any more
  }
}

void Context::submit_and_wait(const std::function<void(const vk::raii::CommandBuffer&)>& record) const {
  vk::raii::CommandBuffers buffers(device_, vk::CommandBufferAllocateInfo{
                                                .commandPool = *pool_,
                                                .level = vk::CommandBufferLevel::ePrimary,
                                                .commandBufferCount = 1});
  const vk::raii::CommandBuffer& cmd = buffers[0];
  cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  record(cmd);
  cmd.end();
  const vk::raii::Fence fence(device_, vk::FenceCreateInfo{});
  const vk::CommandBufferSubmitInfo cmd_info{.commandBuffer = *cmd};
  queue_.submit2(vk::SubmitInfo2{.commandBufferInfoCount = 1, .pCommandBufferInfos = &cmd_info}, *fence);
  if (device_.waitForFences(*fence, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
    throw RuntimeError("waiting for the GPU failed");
}

Submitter::Submitter(const Context& ctx, const std::string& name) : ctx_(&ctx) {
  pool_ = vk::raii::CommandPool(ctx.device(), vk::CommandPoolCreateInfo{
                                                  .flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                  .queueFamilyIndex = ctx.queue_family()});
  cmd_ = std::move(vk::raii::CommandBuffers(ctx.device(), vk::CommandBufferAllocateInfo{
                                                              .commandPool = *pool_,
                                                              .level = vk::CommandBufferLevel::ePrimary,
                                                              .commandBufferCount = 1})[0]);
  fence_ = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo{});
  ctx.name(pool_, name + " command pool");
  ctx.name(cmd_, name);
  ctx.name(fence_, name + " fence");
}

void Submitter::submit_and_wait(const std::function<void(const vk::raii::CommandBuffer&)>& record) {
  cmd_.reset();
  cmd_.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  record(cmd_);
  cmd_.end();
  ctx_->device().resetFences(*fence_);
  const vk::CommandBufferSubmitInfo cmd_info{.commandBuffer = *cmd_};
  ctx_->queue().submit2(vk::SubmitInfo2{.commandBufferInfoCount = 1, .pCommandBufferInfos = &cmd_info}, *fence_);
  if (ctx_->device().waitForFences(*fence_, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
    throw RuntimeError("waiting for the GPU failed");
}

void Context::set_name(vk::ObjectType type, std::uint64_t handle, const std::string& text) const {
  if (!debug_utils_) return;
  device_.setDebugUtilsObjectNameEXT(
      vk::DebugUtilsObjectNameInfoEXT{.objectType = type, .objectHandle = handle, .pObjectName = text.c_str()});
}

}  // namespace pond::gpu
