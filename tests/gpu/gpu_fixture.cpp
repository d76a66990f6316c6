#include "gpu_fixture.h"

#include <cstdlib>
#include <filesystem>

namespace pond::test {
namespace {

// Runs before main (and so before the loader, the layers or Mesa read the environment).
// XDG_CACHE_HOME is where the rest caches: without it the validation layer writes its shader
// validation cache to $HOME/.cache (test_context.cpp checks nothing lands under $HOME).
const bool kEnvironmentSet = [] {
  std::filesystem::create_directories(POND_TEST_MESA_CACHE_DIR);
  std::filesystem::create_directories(POND_TEST_XDG_RUNTIME_DIR);
  std::filesystem::permissions(POND_TEST_XDG_RUNTIME_DIR, std::filesystem::perms::owner_all,
                               std::filesystem::perm_options::replace);
  ::setenv("MESA_SHADER_CACHE_DIR", POND_TEST_MESA_CACHE_DIR, 1);
  ::setenv("XDG_CACHE_HOME", POND_TEST_MESA_CACHE_DIR, 1);
  ::setenv("XDG_RUNTIME_DIR", POND_TEST_XDG_RUNTIME_DIR, 1);
  return true;
}();

}  // namespace

void GpuTest::SetUp() {
  ASSERT_TRUE(kEnvironmentSet);
  ctx_ = std::make_unique<gpu::Context>(gpu::headless_options("", true));
}

void GpuTest::TearDown() {
  if (!ctx_) return;
  ctx_->device().waitIdle();
  const auto messages = ctx_->validation_log().messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), the first: " << messages.front();
}

}  // namespace pond::test
