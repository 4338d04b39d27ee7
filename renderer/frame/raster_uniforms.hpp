#pragma once
// The camera and lighting of a frame's geometry passes: what every raster pass (the fills, the
// silhouette lines, the opaque and unsorted styles) sets as uView, uProjection and uLighting.
#include <glm/glm.hpp>

#include "renderer/gpu/shader_program.hpp"

namespace tlab::render {

struct RasterUniforms {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  int lighting = 1;  // 0 none, 1 headlight, 2 physically based
};

// Sets uView and uProjection of `program` (in use) from `u`.
void setCameraUniforms(const gpu::ShaderProgram& program, const RasterUniforms& u);

// `defines` with TLAB_LIGHTING = `lighting` for a shader that includes frame/surface_shading.glsl:
// its lighting model compiled in rather than read from the uniform uLighting (which then does not
// exist: GL ignores setting it). Unchanged for a model outside 0-2.
gpu::ShaderDefines withLighting(gpu::ShaderDefines defines, int lighting);

}  // namespace tlab::render
