#include "renderer/compose/smart_compositor.hpp"

#include <string>

#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

void composeSmart(FrameContext& frame, const TransparencyFields& fields, const SmartSettings& settings) {
  const FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  gpu::ShaderDefines defines = gpu::joined(buffer.layout().defines(), fields.defines());
  defines.emplace_back("TLAB_MODIFIER", std::to_string(settings.modifier));
  const auto& program = frame.shaders.compute("compose/smart_compose.comp", defines);
  const gpu::Buffer& output = buffer.composeOutput();
  buffer.bindSorted();
  fields.bindCurrent();
  // A pixel without fragments composes to c + T·c_background with c = 0, T = 1: the background,
  // exactly. The buffer is cleared to it, and the shader runs for the pixels with fragments only.
  const glm::vec4 background(glm::vec3(frame.background), 1.0f);
  glClearNamedBufferData(output.id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, &background[0]);
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 9);  // BIND_OUTPUT
  program.use();
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1f(program.uniform("uP"), static_cast<float>(settings.p));
  buffer.dispatchCovered(program);
  finishCompose(frame, output, "compose/smart_compose.comp");
}

}  // namespace tlab::render
