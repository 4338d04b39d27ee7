#include "renderer/ops/screen_space_curvature.hpp"

#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

void computeScreenSpaceCurvature(BucketedKBuffer& buffer, gpu::ShaderCache& shaders, float scale, float lengthUnit,
                                 float projectionY) {
  const auto& program = shaders.compute("ops/screen_space_curvature.comp", buffer.defines());
  buffer.ensureLinks();
  buffer.bind();
  program.use();
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(buffer.pixels()));
  glUniform1f(program.uniform("uScale"), scale * lengthUnit);
  glUniform1f(program.uniform("uPixelsPerUnit"), 0.5f * projectionY * float(buffer.height()));
  glUniform1f(program.uniform("uNear"), buffer.settings().nearPlane);
  glUniform1f(program.uniform("uFar"), buffer.settings().farPlane);
  glUniform1i(program.uniform("uWidth"), buffer.width());
  gpu::dispatchLinear(buffer.pixels());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  gpu::checkGl("ops/screen_space_curvature.comp");
}

}  // namespace tlab::render
