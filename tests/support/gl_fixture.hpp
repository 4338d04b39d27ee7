#pragma once
// One headless context for a whole GL test binary (*_gl_test.cpp): created before the first test,
// destroyed after the last. TLAB_GL chooses it (ctest runs renderer_gl_tests through EGL and
// through OSMesa: tests/renderer/CMakeLists.txt).
#include <gtest/gtest.h>

#include <memory>

#include "renderer/gpu/gpu_context.hpp"

namespace tlab::testing {

class GlEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { context_ = gpu::createHeadlessContext(); }
  void TearDown() override { context_.reset(); }

 private:
  std::unique_ptr<gpu::GpuContext> context_;
};

// Registers the environment once per binary when this header is included in one test file.
inline const ::testing::Environment* const kGlEnvironment =
    ::testing::AddGlobalTestEnvironment(new GlEnvironment);

}  // namespace tlab::testing
