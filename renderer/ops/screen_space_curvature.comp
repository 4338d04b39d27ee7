#version 450 core
// Screen-space curvature (seed 002, Sec. 5.1, after Vergne et al. 2009): the principal curvatures
// are the eigenvalues of the screen-space shape operator, the derivatives of the view-space normal
// across the image, so κ1 + κ2 = its trace = −(∂nx/∂X + ∂ny/∂Y) (negative: convex), X and Y the
// view-space lengths one pixel covers at the fragment's depth z (P11·H / 2z pixels per unit).
// The normal derivatives are central differences between the four neighbours (left, right,
// down, up). Lengths are measured in units of s·r (r the scene's bounding radius, s the style's
// `scale`), so κ does not change with the image size or the scene's units; κ = tanh(κ1 + κ2)
// ∈ (−1, 1); κ = −1 when a neighbour is missing (object boundaries and creases).
#include "frame/fragment_layout.glsl"
#include "kbuffer/kbuffer_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_KB_Z) readonly buffer Z { uint z[]; };
layout(std430, binding = BIND_KB_DATA) readonly buffer Data { uvec2 data[]; };
layout(std430, binding = BIND_KB_LINKS) readonly buffer Links { uint links[]; };
layout(std430, binding = BIND_KB_CURVATURE) writeonly buffer Curvature { float kappa[]; };
uniform uint uPixels;
uniform int uWidth;
uniform float uScale;          // s·r: the length unit of κ1 + κ2
uniform float uPixelsPerUnit;  // P11·H / 2: pixels per view-space unit at eye depth 1
uniform float uNear;
uniform float uFar;

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uPixels) return;
  uint base = slotOf(pixel, 0u);
  for (uint layer = 0u; layer < uint(TLAB_K); ++layer) {
    uint f = base + layer;
    if (z[f] == KB_EMPTY) break;
    uint l = links[f];
    vec3 n[4];
    bool complete = true;
    for (int d = 0; d < 4; ++d) {
      uint layerInQ = linkLayer(l, d);
      complete = complete && layerInQ != KB_NO_LINK;
      if (layerInQ == KB_NO_LINK) break;
      int q = int(pixel) + kDirections[d].y * uWidth + kDirections[d].x;
      n[d] = decodeNormal(data[slotOf(uint(q), layerInQ)].y);
    }
    if (!complete) {
      kappa[f] = -1.0;  // a missing neighbour
      continue;
    }
    vec3 left = n[0], right = n[1], down = n[2], up = n[3];
    float divergence = 0.5 * (right.x - left.x) + 0.5 * (up.y - down.y);  // per pixel
    float depth = uNear + depthOfShapeFirst(z[f]) * (uFar - uNear);
    float pixelsPerLength = uScale * uPixelsPerUnit / max(depth, 1e-6);
    kappa[f] = tanh(-pixelsPerLength * divergence);  // κ = tanh(κ1 + κ2)
  }
}
