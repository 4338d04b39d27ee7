#pragma once
// The camera and lighting of a frame's geometry passes: what every raster pass (the fills, the
// silhouette lines, the opaque and unsorted styles) sets as uView and uProjection, and the lighting
// model the shading passes compile in (withLighting).
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

// `defines` with TLAB_LIGHTING = `lighting` (0-2), for a shader that calls shadeSurface
// (frame/surface_shading.glsl): the model compiled in.
gpu::ShaderDefines withLighting(gpu::ShaderDefines defines, int lighting);

}  // namespace tlab::render
