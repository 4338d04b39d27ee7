// A shader the driver cannot compile: the GlError is one line that names the shader file and
// carries the driver's log (no line breaks, no trailing NULs), so `tlab` can print it as its one
// error line. The fault is injected through a define, which is inserted after the #version line.
#include <gtest/gtest.h>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/shader_program.hpp"
#include "tests/support/gl_fixture.hpp"

namespace tlab::gpu {
namespace {

TEST(ShaderErrors, ACompileFailureIsOneLineNamingTheShader) {
  const ShaderDefines broken = {{"TLAB_PHASE", "1\nthis is not GLSL;"}};
  try {
    ShaderProgram::compute("buffer/prefix_sum.comp", broken);
    FAIL() << "the broken shader compiled";
  } catch (const GlError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("shader buffer/prefix_sum.comp failed to compile: ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find('\0'), std::string::npos) << message;
    EXPECT_GT(message.size(), std::string("shader buffer/prefix_sum.comp failed to compile: ").size()) << "no driver log";
  }
}

}  // namespace
}  // namespace tlab::gpu
