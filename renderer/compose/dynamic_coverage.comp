#version 450 core
// Where targets are drawn (Elmqvist et al., seed 004, Alg. 2 line 2): per pixel the farthest
// target among the surfaces dynamic transparency draws (compose/dynamic_surfaces.glsl), as
// 1 + its object id (0: none) and its eye-space depth. The host turns this into the
// low-resolution alpha mask (ops/alpha_mask).
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
#include "frame/surface_shading.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
layout(std430, binding = 10) writeonly buffer CoverTarget { uint coverTarget[]; };
layout(std430, binding = 11) writeonly buffer CoverDepth { float coverDepth[]; };
uniform int uWidth;
uniform int uHeight;
#include "compose/dynamic_surfaces.glsl"

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uint(uWidth * uHeight)) return;
  uint target = 0u;
  gSurfaceCount = 0;
  if (pixelCount[pixel] > 0u) collectSurfaces(pixelHead[pixel], pixelCount[pixel]);
  float depth = 0.0;
  for (int k = 0; k < gSurfaceCount && target == 0u; ++k)
    if (isTarget(gSurface[k])) {
      target = objectOf(gSurface[k]) + 1u;
      depth = depthOf(gSurface[k]);
    }
  coverTarget[pixel] = target;
  coverDepth[pixel] = depth;
}
