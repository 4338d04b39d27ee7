#include "renderer/compose/style_file_compositor.hpp"

#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/ops/style_file_stage.hpp"

namespace tlab::render {

void composeStyleFile(FrameContext& frame, const StyleProgram& style, const gpu::Buffer* values) {
  FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  gpu::ShaderDefines defines = buffer.layout().defines();
  if (values) defines = styleStageDefines(defines);
  const auto& program = style.compile(frame.shaders, "compose/style_file_compose.comp", defines);
  gpu::Buffer output(buffer.pixels() * sizeof(glm::vec4));
  buffer.bindSorted();
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 9);  // BIND_OUTPUT
  if (values) values->bindBase(GL_SHADER_STORAGE_BUFFER, 20);  // BIND_STYLE_VALUE_IN
  program.use();
  setStyleFrameUniforms(program, frame);
  style.setUniforms(program);
  dispatchCompose(frame, output, buffer.pixels(), "compose/style_file_compose.comp");
}

}  // namespace tlab::render
