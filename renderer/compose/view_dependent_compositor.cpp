#include "renderer/compose/view_dependent_compositor.hpp"

#include "renderer/gpu/gl_error.hpp"
#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

namespace {
// Binding points of compose/view_dependent_compose.comp and ops/silhouette_lines.frag.
constexpr GLuint kBindOutput = 9, kBindPositions = 10, kBindTriangles = 11, kBindVertexAlpha = 12, kBindVisibleDepth = 13;

// Rasterizes the silhouette segments as 1-pixel lines into the output buffer, with no attachment
// (the fragment shader writes the buffer).
// Transparent objects' lines (the first `transparentCount`) are tested against the depth of F1,
// the others against the hiding depth (compose/view_dependent_compose.comp).
void drawLines(FrameContext& frame, const std::vector<SilhouetteSegment>& segments, std::size_t transparentCount,
               glm::vec3 color) {
  if (segments.empty()) return;
  const gpu::Buffer vertices(segments.size() * sizeof(SilhouetteSegment), segments.data());
  const gpu::VertexArray vao = gpu::makeVertexArray();
  glEnableVertexArrayAttrib(vao.id(), 0);
  glVertexArrayVertexBuffer(vao.id(), 0, vertices.id(), 0, sizeof(glm::vec3));
  glVertexArrayAttribFormat(vao.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao.id(), 0, 0);
  const gpu::Framebuffer fbo = gpu::makeFramebuffer();
  glNamedFramebufferParameteri(fbo.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, frame.width);
  glNamedFramebufferParameteri(fbo.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, frame.height);
  const auto& program = frame.shaders.graphics("ops/silhouette_lines.vert", "ops/silhouette_lines.frag");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, frame.width, frame.height);
  glDisable(GL_DEPTH_TEST);
  program.use();
  setCameraUniforms(program, frame.raster);
  glUniform1i(program.uniform("uWidth"), frame.width);
  glUniform1i(program.uniform("uHeight"), frame.height);
  glUniform3fv(program.uniform("uLineColor"), 1, &color[0]);
  glUniform1f(program.uniform("uDepthTolerance"), 0.005f);
  glBindVertexArray(vao.id());
  glUniform1i(program.uniform("uLimit"), 1);
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(transparentCount * 2));
  glUniform1i(program.uniform("uLimit"), 0);
  glDrawArrays(GL_LINES, static_cast<GLint>(transparentCount * 2), static_cast<GLsizei>((segments.size() - transparentCount) * 2));
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
}
}  // namespace

void composeViewDependent(FrameContext& frame, const ViewDependentAlpha& alpha, const ViewDependentSettings& settings) {
  FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  const auto& program = frame.shaders.compute("compose/view_dependent_compose.comp",
                                              gpu::joined(buffer.layout().defines(), settings.shading.defines()));
  gpu::Buffer output(buffer.pixels() * sizeof(glm::vec4)), visibleDepth(buffer.pixels() * 2 * sizeof(float));
  buffer.bindSorted();
  frame.gpuScene.bindObjectTable();
  output.bindBase(GL_SHADER_STORAGE_BUFFER, kBindOutput);
  alpha.positions().bindBase(GL_SHADER_STORAGE_BUFFER, kBindPositions);
  alpha.triangles().bindBase(GL_SHADER_STORAGE_BUFFER, kBindTriangles);
  alpha.vertexAlpha().bindBase(GL_SHADER_STORAGE_BUFFER, kBindVertexAlpha);
  visibleDepth.bindBase(GL_SHADER_STORAGE_BUFFER, kBindVisibleDepth);
  program.use();
  glUniform1i(program.uniform("uWidth"), buffer.width());
  glUniform1i(program.uniform("uHeight"), buffer.height());
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform2f(program.uniform("uProjectionScale"), frame.raster.projection[0][0], frame.raster.projection[1][1]);
  glUniformMatrix4fv(program.uniform("uView"), 1, GL_FALSE, &frame.raster.view[0][0]);
  glUniform1i(program.uniform("uExplicitBoundaries"), settings.explicitBoundaries ? 1 : 0);
  glUniform1f(program.uniform("uAlphaOpaque"), settings.alphaOpaque);
  glUniform1f(program.uniform("uAlphaBackground"), settings.alphaBackground);
  glUniform1i(program.uniform("uAdditiveBlend"), settings.additiveBlend ? 1 : 0);
  settings.shading.setUniforms(program, buffer.width(), buffer.height());
  gpu::dispatchLinear(buffer.pixels());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  if (settings.lines) drawLines(frame, alpha.silhouettes(), alpha.transparentCount(), settings.lineColor);
  readOutputBuffer(output, frame.image);
  gpu::checkGl("compose/view_dependent_compose.comp");
}

}  // namespace tlab::render
