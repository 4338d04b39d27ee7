#include "renderer/compose/blend_compositor.hpp"

#include "renderer/gpu/gl_error.hpp"
#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

void composeBlend(FrameContext& frame, float alpha) {
  FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  const auto& program = frame.shaders.compute("compose/blend.comp", buffer.layout().defines());
  const gpu::Buffer& output = buffer.composeOutput();
  buffer.bindSorted();
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 9);  // BIND_OUTPUT
  program.use();
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(buffer.pixels()));
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1f(program.uniform("uAlpha"), alpha);
  dispatchCompose(frame, output, buffer.pixels(), "compose/blend.comp");
}

}  // namespace tlab::render
