// The Vulkan context: explicit device choice, the validation messenger really reports, the test
// environment stays inside the build tree.
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.h"
#include "gpu/buffer.h"
#include "gpu/gpu_solver.h"
#include "gpu/headless.h"
#include "gpu_fixture.h"
#include "scene/scene.h"

extern char** environ;

namespace pond::test {
namespace {

namespace fs = std::filesystem;

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

// Another architecture's driver on the ICD path (Debian multiarch: mesa-vulkan-drivers:i386 or
// :arm64 beside the native one) makes the loader report that it cannot load that library. The
// loader skips it; it is not a validation message, and a context still comes up on the device.
TEST(ContextValidation, AForeignArchitectureDriverIsNotAValidationMessage) {
  const fs::path dir = fs::path(POND_TEST_TMP_DIR) / "foreign-icd";
  fs::create_directories(dir);
  // The ELF header of an aarch64 shared object (x86-64 hosts) or of an x86-64 one (others): the
  // loader's dlopen refuses it as a library of another machine.
  unsigned char elf[64] = {0x7f, 'E', 'L', 'F', 2, 1, 1};
  elf[16] = 3;  // e_type: ET_DYN
#if defined(__aarch64__)
  elf[18] = 62;  // e_machine: EM_X86_64
#else
  elf[18] = 183;  // e_machine: EM_AARCH64
#endif
  elf[20] = 1;  // e_version
  std::ofstream(dir / "libvulkan_foreign.so", std::ios::binary).write(reinterpret_cast<const char*>(elf), sizeof elf);
  std::ofstream(dir / "foreign_icd.json")
      << R"({"file_format_version": "1.0.0", "ICD": {"library_path": ")" << (dir / "libvulkan_foreign.so").string()
      << R"(", "api_version": "1.3.0"}})";
  const std::string json = (dir / "foreign_icd.json").string();
  ::setenv("VK_ADD_DRIVER_FILES", json.c_str(), 1);
  struct Unset {
    ~Unset() { ::unsetenv("VK_ADD_DRIVER_FILES"); }
  } unset;
  const gpu::Context ctx(gpu::headless_options("", true));
  EXPECT_FALSE(ctx.device_name().empty());
  const auto messages = ctx.validation_log().messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " message(s), the first: " << messages.front();
}

// Every file this process has open (/proc/self/fd) or mapped (/proc/self/maps).
std::vector<std::string> open_and_mapped_files() {
  std::vector<std::string> files;
  std::error_code ec;
  for (const fs::directory_entry& fd : fs::directory_iterator("/proc/self/fd", ec)) {
    const fs::path target = fs::read_symlink(fd.path(), ec);
    if (!ec && target.is_absolute()) files.push_back(target.string());
  }
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);)
    if (const std::size_t slash = line.find('/'); slash != std::string::npos) files.push_back(line.substr(slash));
  return files;
}

bool inside(const std::string& file, const fs::path& dir) {
  const std::string prefix = fs::weakly_canonical(dir).string() + "/";
  return file.compare(0, prefix.size(), prefix) == 0;
}

bool mesa_driver(const gpu::Context& ctx) {
  using D = vk::DriverId;
  const D id = ctx.physical()
                   .getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceDriverProperties>()
                   .get<vk::PhysicalDeviceDriverProperties>()
                   .driverID;
  for (D mesa : {D::eMesaLlvmpipe, D::eMesaRadv, D::eIntelOpenSourceMESA, D::eMesaTurnip, D::eMesaV3Dv,
                 D::eMesaPanvk, D::eMesaVenus, D::eMesaDozen, D::eMesaNvk, D::eImaginationOpenSourceMESA})
    if (id == mesa) return true;
  return false;
}

bool env_true(const char* name) {
  const char* v = std::getenv(name);
  return v && (std::string_view(v) == "1" || std::string_view(v) == "true");
}

// A compute run with the fixture's environment: the GPU solver's pipelines compiled and
// dispatched. Then no file under $HOME/.cache is open or mapped, and on a Mesa driver (vk::DriverId:
// the check is about Mesa's disk cache, which other drivers do not have) the cache Mesa opened is
// the build tree's, which is what MESA_SHADER_CACHE_DIR is for. WritesNothingUnderHomeOrTmp runs
// this test again in a fresh $HOME.
using ContextEnvironment = GpuTest;

TEST_F(ContextEnvironment, ComputeKeepsItsFilesInTheBuildTree) {
  gpu::GpuSolver solver(ctx(), sim::build_model(scene::load_scene("")));
  solver.advance(3);
  EXPECT_EQ(solver.read_state().nodes(), solver.model().nodes());
  const std::vector<std::string> files = open_and_mapped_files();
  if (const char* home = std::getenv("HOME")) {
    for (const std::string& f : files)
      EXPECT_FALSE(inside(f, fs::path(home) / ".cache")) << f << " is under $HOME/.cache";
  }
  if (!mesa_driver(ctx())) {
    std::printf("not a Mesa driver: no Mesa shader cache to look for\n");
  } else if (env_true("MESA_SHADER_CACHE_DISABLE") || env_true("MESA_GLSL_CACHE_DISABLE")) {
    std::printf("Mesa's shader cache is disabled in this environment: not looked for\n");
  } else {
    const auto in_cache = [](const std::string& f) { return inside(f, POND_TEST_MESA_CACHE_DIR); };
    EXPECT_TRUE(std::any_of(files.begin(), files.end(), in_cache))
        << "Mesa has no cache file open or mapped in " << POND_TEST_MESA_CACHE_DIR;
  }
}

// The fixture's promise, checked where it can fail: the test above in a child process whose $HOME
// (with an empty .cache, as a real one has) and $TMPDIR are fresh folders, and whose environment
// lacks every variable the fixture sets (so only the fixture can set them). Afterwards both
// folders are still empty: neither the driver nor the loader nor the validation layer wrote there.
// (A driver that caches outside XDG_CACHE_HOME fails this: point its own variable into the build
// tree in gpu_fixture.cpp, as for Mesa.)
TEST(ContextIsolation, WritesNothingUnderHomeOrTmp) {
  const std::string tag = "fresh-home-" + std::to_string(::getpid());
  const fs::path root = fs::path(POND_TEST_TMP_DIR) / tag;
  const fs::path home = root / "home", tmp = root / "tmp";
  const fs::path report = fs::path(POND_TEST_TMP_DIR) / (tag + ".xml");  // the child's gtest report
  fs::remove_all(root);
  fs::remove(report);
  fs::create_directories(home / ".cache");
  fs::create_directories(tmp);
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string_view var(*e);
    const std::string_view name = var.substr(0, var.find('='));
    if (name != "HOME" && name != "TMPDIR" && name != "MESA_SHADER_CACHE_DIR" && name != "XDG_CACHE_HOME" &&
        name != "XDG_RUNTIME_DIR" && !name.starts_with("GTEST_"))
      env.emplace_back(var);
  }
  env.push_back("HOME=" + home.string());
  env.push_back("TMPDIR=" + tmp.string());
  const std::string exe = fs::read_symlink("/proc/self/exe").string();
  std::vector<std::string> args = {exe, "--gtest_filter=ContextEnvironment.ComputeKeepsItsFilesInTheBuildTree",
                                   "--gtest_output=xml:" + report.string()};
  std::vector<char*> argv, envp;
  for (std::string& a : args) argv.push_back(a.data());
  for (std::string& e : env) envp.push_back(e.data());
  argv.push_back(nullptr);
  envp.push_back(nullptr);
  std::fflush(stdout);
  pid_t pid = 0;
  ASSERT_EQ(::posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), envp.data()), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the child run failed (its output is above)";
  std::ifstream in(report);
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_NE(xml.find("<testsuites tests=\"1\" failures=\"0\""), std::string::npos)
      << "the child did not run exactly the one test: " << xml;
  std::vector<std::string> written;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(root))
    if (e.path() != home && e.path() != home / ".cache" && e.path() != tmp) written.push_back(e.path().string());
  EXPECT_TRUE(written.empty()) << written.size() << " file(s) written outside the build tree, the first: "
                               << written.front();
  if (written.empty()) {
    fs::remove_all(root);
    fs::remove(report);
  }
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
