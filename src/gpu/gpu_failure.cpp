#include "gpu/gpu_failure.h"

namespace pond::gpu {

void rethrow_as_gpu_failure(const std::string& device, const char* doing) {
  try {
    throw;
  } catch (const vk::DeviceLostError&) {
    throw GpuFailure(GpuFailure::Kind::device_lost,
                     "the Vulkan device '" + device + "' was lost (VK_ERROR_DEVICE_LOST) " + doing);
  } catch (const vk::OutOfDeviceMemoryError&) {
    throw GpuFailure(GpuFailure::Kind::out_of_memory,
                     "the Vulkan device '" + device + "' is out of device memory " + doing);
  } catch (const vk::OutOfHostMemoryError&) {
    throw GpuFailure(GpuFailure::Kind::out_of_memory,
                     "the Vulkan device '" + device + "' is out of host memory " + doing);
  } catch (const vk::SystemError& e) {
    throw RuntimeError("Vulkan failed on '" + device + "' " + doing + ": " + e.what());
  }
}

}  // namespace pond::gpu
