#include "renderer/compose/illustrative_compositor.hpp"

#include <stdexcept>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

namespace {
constexpr GLuint kBindOutput = 9;  // BIND_OUTPUT in frame/fragment_layout.glsl
}  // namespace

void composeIllustrative(FrameContext& frame, const IllustrativeSettings& settings) {
  FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  const FragmentProperties stored = buffer.layout().properties;
  if ((settings.opacity == IllustrativeSettings::Opacity::NormalVariation && !stored.has(FragmentProperty::NormalZGradient)) ||
      (settings.stripes != 0 && !stored.has(FragmentProperty::StGradient)))
    throw std::logic_error("normal variation and stripes need the screen-space derivatives stored at fill time");
  const auto& program =
      frame.shaders.compute("compose/illustrative_compose.comp", gpu::joined(buffer.layout().defines(), settings.defines()));
  gpu::Buffer output(buffer.pixels() * sizeof(glm::vec4));
  buffer.bindSorted();
  frame.gpuScene.bindObjectTable();
  output.bindBase(GL_SHADER_STORAGE_BUFFER, kBindOutput);
  program.use();
  glUniform1i(program.uniform("uWidth"), buffer.width());
  glUniform1i(program.uniform("uHeight"), buffer.height());
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform2f(program.uniform("uProjectionScale"), frame.raster.projection[0][0], frame.raster.projection[1][1]);
  settings.setUniforms(program, buffer.width(), buffer.height());
  dispatchCompose(frame, output, buffer.pixels(), "compose/illustrative_compose.comp");
}

}  // namespace tlab::render
