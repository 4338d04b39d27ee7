#include "renderer/compose/curvature_compositor.hpp"

#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

void composeCurvature(FrameContext& frame, const BucketedKBuffer& buffer, CurvatureStylization stylization,
                      float alpha, const CurvatureShadingFunction& shading, const CurvatureOpacityFunction& opacity) {
  auto defines = buffer.defines();
  defines.emplace_back("TLAB_STYLIZATION", std::to_string(int(stylization)));
  const auto& program = frame.shaders.compute("compose/curvature_compose.comp", defines);
  // The transfer functions as one table: tf1 (vec4 per sample), then tf2 (row = depth).
  std::vector<glm::vec4> table;
  for (const auto& v : shading.samples()) table.emplace_back(v, 1.0f);
  const auto& o = opacity.samples();
  for (std::size_t i = 0; i < o.size(); i += 4) table.emplace_back(o[i], o[i + 1], o[i + 2], o[i + 3]);
  const gpu::Buffer transfer(table.size() * sizeof(glm::vec4), table.data());
  gpu::Buffer output(buffer.pixels() * sizeof(glm::vec4));
  buffer.bind();
  transfer.bindBase(GL_SHADER_STORAGE_BUFFER, 10);  // BIND_KB_TRANSFER
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 9);     // BIND_KB_OUTPUT
  program.use();
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(buffer.pixels()));
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1f(program.uniform("uAlpha"), alpha);
  dispatchCompose(frame, output, buffer.pixels(), "compose/curvature_compose.comp");
}

}  // namespace tlab::render
