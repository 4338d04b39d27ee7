#include "renderer/frame/fragment_capture.hpp"

#include "renderer/gpu/gl.hpp"

namespace tlab::render {

void beginFragmentCapture(const gpu::Framebuffer& framebuffer, int width, int height, const gpu::ShaderProgram& program,
                          const RasterUniforms& u) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  program.use();
  setCameraUniforms(program, u);
  glUniform1i(program.uniform("uWidth"), width);
}

void endFragmentCapture(const GpuScene& scene, const gpu::ShaderProgram& program) {
  scene.bindObjectTable();
  scene.draw(program.uniform("uPrimitiveBase"));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace tlab::render
