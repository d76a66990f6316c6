#pragma once
// The base of every GPU test: a Vulkan context with VK_LAYER_KHRONOS_validation, synchronization
// validation and a messenger; any validation message (warning or error) fails the test.
//
// Mesa's shader cache, XDG_CACHE_HOME (the validation layer's cache) and XDG_RUNTIME_DIR point
// into the build tree (set before any Vulkan call, see gpu_fixture.cpp), so the tests write nothing
// outside it (ContextEnvironment in test_context.cpp checks it).
#include <gtest/gtest.h>

#include <memory>

#include "gpu/context.h"
#include "gpu/headless.h"

namespace pond::test {

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  const gpu::Context& ctx() const { return *ctx_; }

 private:
  std::unique_ptr<gpu::Context> ctx_;
};

}  // namespace pond::test
