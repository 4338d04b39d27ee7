#include "renderer/compose/blend_compositor.hpp"

#include "renderer/gpu/gl_error.hpp"
#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

// The lists sorted by the fill's sort pass, or, when the fill left them unsorted (FillSpec::
// sortsInCompose), sorted here as they are blended (compose/blend.comp, TLAB_FUSED).
void composeBlend(FrameContext& frame, float alpha) {
  FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  gpu::ShaderDefines defines = buffer.layout().defines();
  if (!buffer.sorted()) {
    defines.emplace_back("TLAB_FUSED", "1");
    if (buffer.bindUnsorted()) defines.emplace_back("TLAB_SLOTS", "1");
  } else {
    buffer.bindSorted();
  }
  const auto& program = frame.shaders.compute("compose/blend.comp", defines);
  const gpu::Buffer& output = buffer.composeOutput();
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 9);  // BIND_OUTPUT
  program.use();
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(buffer.pixels()));
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1f(program.uniform("uAlpha"), alpha);
  dispatchCompose(frame, output, buffer.pixels(), "compose/blend.comp");
}

}  // namespace tlab::render
