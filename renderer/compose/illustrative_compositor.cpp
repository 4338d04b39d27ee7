#include "renderer/compose/illustrative_compositor.hpp"

#include <stdexcept>

#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

namespace {
constexpr GLuint kBindOutput = 9;  // BIND_OUTPUT in buffer/fragment_layout.glsl
constexpr GLuint kBindLinks = 10;  // BIND_LINKS in ops/field_bindings.glsl
}  // namespace

void composeIllustrative(FrameContext& frame, const IllustrativeSettings& settings, const gpu::Buffer* links) {
  FragmentBuffer& buffer = *frame.buffer;
  if (settings.needsScreenDerivatives() && !links)
    throw std::logic_error("normal variation and stripes need the neighbour links of the connect pass");
  gpu::ShaderDefines defines = buffer.layout().defines();
  if (links) defines.emplace_back("TLAB_HAS_LINKS", "1");
  const auto& program = frame.shaders.compute("compose/illustrative_compose.comp", defines);
  gpu::Buffer output(buffer.pixels() * sizeof(glm::vec4));
  buffer.bindSorted();
  frame.gpuScene.bindObjectTable();
  output.bindBase(GL_SHADER_STORAGE_BUFFER, kBindOutput);
  if (links) links->bindBase(GL_SHADER_STORAGE_BUFFER, kBindLinks);
  program.use();
  glUniform1i(program.uniform("uWidth"), buffer.width());
  glUniform1i(program.uniform("uHeight"), buffer.height());
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform2f(program.uniform("uProjectionScale"), frame.raster.projection[0][0], frame.raster.projection[1][1]);
  settings.setUniforms(program, buffer.width(), buffer.height());
  gpu::dispatchLinear(buffer.pixels());
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  readOutputBuffer(output, frame.image);
  gpu::checkGl("compose/illustrative_compose.comp");
}

}  // namespace tlab::render
