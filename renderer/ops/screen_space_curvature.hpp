#pragma once
// Screen-space curvature per fragment of the bucketed k-buffer (seed 002, Sec. 5.1).
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/kbuffer/bucketed_kbuffer.hpp"

namespace tlab::render {

// κ = tanh(κ1 + κ2) for every slot from its neighbours' view-facing normals (the links of
// findBucketNeighbors), κ1 + κ2 ≈ −scale·(∂nx/∂x + ∂ny/∂y) by central differences in pixels, so
// convexities are negative; κ = −1 where a neighbour is missing. Written to buffer.curvature().
// The CPU reference is kbuffer::screenSpaceCurvature.
void computeScreenSpaceCurvature(BucketedKBuffer& buffer, gpu::ShaderCache& shaders, float scale);

}  // namespace tlab::render
