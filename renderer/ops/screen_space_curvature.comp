#version 450 core
// Screen-space curvature (seed 002, Sec. 5.1, after Vergne et al.): for each fragment with all
// four neighbours (left, right, down, up), κ1 + κ2 ≈ −s·(∂nx/∂x + ∂ny/∂y) from the neighbours'
// view-facing normals by central differences, mapped as κ = tanh(κ1 + κ2) ∈ (−1, 1), −1 convex;
// κ = −1 when a neighbour is missing (object boundaries and creases).
#include "buffer/fragment_layout.glsl"
#include "kbuffer/kbuffer_layout.glsl"
#include "buffer/compute_index.glsl"
layout(std430, binding = BIND_KB_Z) readonly buffer Z { uint z[]; };
layout(std430, binding = BIND_KB_DATA) readonly buffer Data { uvec2 data[]; };
layout(std430, binding = BIND_KB_LINKS) readonly buffer Links { uint links[]; };
layout(std430, binding = BIND_KB_CURVATURE) writeonly buffer Curvature { float kappa[]; };
uniform uint uPixels;
uniform int uWidth;
uniform float uScale;  // s: pixels per unit of the normal's change

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
    float divergence = 0.5 * (right.x - left.x) + 0.5 * (up.y - down.y);
    kappa[f] = tanh(-uScale * divergence);  // κ = tanh(κ1 + κ2)
  }
}
