#include "renderer/compose/smart_compositor.hpp"

#include <string>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

void composeSmart(FrameContext& frame, const TransparencyFields& fields, const SmartSettings& settings) {
  const FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  gpu::ShaderDefines defines = buffer.layout().defines();
  for (const auto& d : fields.defines()) defines.push_back(d);
  defines.emplace_back("TLAB_MODIFIER", std::to_string(settings.modifier));
  const auto& program = frame.shaders.compute("compose/smart_compose.comp", defines);
  gpu::Buffer output(buffer.pixels() * sizeof(glm::vec4));
  buffer.bindSorted();
  fields.bindCurrent();
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 9);  // BIND_OUTPUT
  program.use();
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(buffer.pixels()));
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1f(program.uniform("uP"), static_cast<float>(settings.p));
  dispatchCompose(frame, output, buffer.pixels(), "compose/smart_compose.comp");
}

}  // namespace tlab::render
