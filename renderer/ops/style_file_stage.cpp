#include "renderer/ops/style_file_stage.hpp"

#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/gpu/gl_error.hpp"
#include "renderer/ops/connect_pass.hpp"

namespace tlab::render {

namespace {
constexpr GLuint kValueIn = 20, kValueOut = 21;  // BIND_STYLE_VALUE_IN/OUT of ops/style_file_prelude.glsl
}

void setStyleFrameUniforms(const gpu::ShaderProgram& program, const FrameContext& frame) {
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(std::size_t(frame.width) * frame.height));
  glUniform1ui(program.uniform("uWidth"), static_cast<GLuint>(frame.width));
  glUniform1ui(program.uniform("uHeight"), static_cast<GLuint>(frame.height));
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1f(program.uniform("uNear"), frame.camera.nearPlane);
  glUniform1f(program.uniform("uFar"), frame.camera.farPlane);
}

gpu::ShaderDefines styleStageDefines(const gpu::ShaderDefines& layoutDefines) {
  gpu::ShaderDefines defines = layoutDefines;
  defines.emplace_back("TLAB_STYLE_VALUES", "1");
  return defines;
}

std::unique_ptr<gpu::Buffer> runStyleFileStage(FrameContext& frame, const StyleProgram& style, int iterations) {
  const FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  // The links only: the connect pass's α/β/γ are smart transparency's, unused here.
  SmartSettings linksOnly;
  linksOnly.silhouettes = linksOnly.halos = false;
  const auto fields = connectFragments(buffer, frame.shaders, linksOnly, frame.scene.boundingSphere().radius);
  const auto& program = style.compile(frame.shaders, "ops/style_file_stage.comp", styleStageDefines(buffer.layout().defines()));
  const std::size_t n = std::max<std::size_t>(buffer.fragmentCount(), 1);
  const std::vector<float> zeros(n, 0.0f);
  auto current = std::make_unique<gpu::Buffer>(n * sizeof(float), zeros.data());
  auto next = std::make_unique<gpu::Buffer>(n * sizeof(float), zeros.data());
  buffer.bindSorted();
  fields->links().bindBase(GL_SHADER_STORAGE_BUFFER, 10);  // BIND_LINKS
  program.use();
  setStyleFrameUniforms(program, frame);
  style.setUniforms(program);
  glUniform1ui(program.uniform("uFragments"), static_cast<GLuint>(buffer.fragmentCount()));
  for (int i = 0; i <= iterations && buffer.fragmentCount() > 0; ++i) {
    current->bindBase(GL_SHADER_STORAGE_BUFFER, kValueIn);
    next->bindBase(GL_SHADER_STORAGE_BUFFER, kValueOut);
    glUniform1i(program.uniform("uIteration"), i);
    gpu::dispatchLinear(buffer.fragmentCount());
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(current, next);
  }
  gpu::checkGl("ops/style_file_stage.comp");
  return current;
}

}  // namespace tlab::render
