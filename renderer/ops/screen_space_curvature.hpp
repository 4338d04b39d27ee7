#pragma once
// Screen-space curvature per fragment of the bucketed k-buffer (seed 002, Sec. 5.1).
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/kbuffer/bucketed_kbuffer.hpp"

namespace tlab::render {

// κ = tanh(κ1 + κ2) for every slot from its neighbours' view-facing normals (the links of
// findBucketNeighbors), after Vergne et al. 2009: κ1 + κ2 = −(∂nx/∂X + ∂ny/∂Y) with X, Y view-space
// lengths in units of scale·lengthUnit, from central differences in pixels and the pixel's
// footprint at the fragment's depth (`projectionY` = P[1][1]); so κ is the same at every image
// size. Convexities are negative; κ = −1 where a neighbour is missing. Written to
// buffer.curvature(). The CPU reference is kbuffer::screenSpaceCurvature (with the per-pixel scale).
// (The defaults serve timing runs, where only the work matters.)
void computeScreenSpaceCurvature(BucketedKBuffer& buffer, gpu::ShaderCache& shaders, float scale, float lengthUnit = 1.0f,
                                 float projectionY = 1.0f);

}  // namespace tlab::render
