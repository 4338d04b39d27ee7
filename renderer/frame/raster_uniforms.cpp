#include "renderer/frame/raster_uniforms.hpp"

#include <string>

#include "renderer/gpu/gl.hpp"

namespace tlab::render {

void setCameraUniforms(const gpu::ShaderProgram& program, const RasterUniforms& u) {
  glUniformMatrix4fv(program.uniform("uView"), 1, GL_FALSE, &u.view[0][0]);
  glUniformMatrix4fv(program.uniform("uProjection"), 1, GL_FALSE, &u.projection[0][0]);
}

gpu::ShaderDefines withLighting(gpu::ShaderDefines defines, int lighting) {
  defines.emplace_back("TLAB_LIGHTING", std::to_string(lighting));
  return defines;
}

}  // namespace tlab::render
