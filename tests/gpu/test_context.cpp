// The Vulkan context: explicit device choice, the validation messenger really reports, the test
// environment stays inside the build tree.
#include <cstdlib>
#include <string>

#include "core/errors.h"
#include "gpu/buffer.h"
#include "gpu/headless.h"
#include "gpu_fixture.h"

namespace pond::test {
namespace {

using ContextTest = GpuTest;

TEST_F(ContextTest, ChoosesAComputeDevice) {
  EXPECT_FALSE(ctx().device_name().empty());
  std::printf("device: %s\n", ctx().device_name().c_str());
}

TEST_F(ContextTest, DeviceBySubstringIsCaseInsensitive) {
  const std::string name = ctx().device_name();
  std::string upper = name.substr(0, 4);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const gpu::Context other(gpu::headless_options(upper, true));
  EXPECT_EQ(other.device_name(), name);
  EXPECT_TRUE(other.validation_log().messages().empty());
}

TEST_F(ContextTest, UnknownDeviceIsAnInputErrorListingTheDevices) {
  try {
    gpu::Context other(gpu::headless_options("no-such-gpu-xyz", false));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(ctx().device_name()), std::string::npos) << e.what();
  }
}

// The messenger is live: a deliberate misuse is reported into the log (and this test then clears
// the expectation by checking the log of a separate context).
TEST(ContextValidation, MessengerReportsMisuse) {
  gpu::Context bad(gpu::headless_options("", true));
  // A zero-sized buffer is invalid usage (VUID-VkBufferCreateInfo-size-00912).
  try {
    const vk::raii::Buffer b(bad.device(), vk::BufferCreateInfo{.size = 0, .usage = vk::BufferUsageFlagBits::eStorageBuffer});
  } catch (const std::exception&) {
  }
  EXPECT_GE(bad.validation_log().count(), 1u);
}

TEST_F(ContextTest, EnvironmentPointsIntoTheBuildTree) {
  EXPECT_STREQ(std::getenv("MESA_SHADER_CACHE_DIR"), POND_TEST_MESA_CACHE_DIR);
  EXPECT_STREQ(std::getenv("XDG_RUNTIME_DIR"), POND_TEST_XDG_RUNTIME_DIR);
}

TEST(MemoryTypeChoice, RequiredFlagsAndPreferences) {
  vk::PhysicalDeviceMemoryProperties props{};
  using MP = vk::MemoryPropertyFlagBits;
  props.memoryTypeCount = 3;
  props.memoryTypes[0].propertyFlags = MP::eDeviceLocal;
  props.memoryTypes[1].propertyFlags = MP::eHostVisible | MP::eHostCoherent;
  props.memoryTypes[2].propertyFlags = MP::eHostVisible | MP::eHostCoherent | MP::eHostCached;
  EXPECT_EQ(gpu::choose_memory_type(props, 0b111, MP::eDeviceLocal, {}), 0u);
  EXPECT_EQ(gpu::choose_memory_type(props, 0b111, MP::eHostVisible, MP::eHostCached | MP::eHostCoherent), 2u);
  EXPECT_EQ(gpu::choose_memory_type(props, 0b011, MP::eHostVisible, MP::eHostCached), 1u);
  EXPECT_THROW(gpu::choose_memory_type(props, 0b110, MP::eDeviceLocal, {}), RuntimeError);
}

}  // namespace
}  // namespace pond::test
