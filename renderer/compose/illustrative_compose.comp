#version 450 core
// The IRIS local styles on the illustration buffer: every fragment of each pixel's sorted list is
// shaded by frame/illustrative_shading.glsl, faded to the silhouette colour by a Sobel filter on
// its own layer (the same layer index in the 3x3 neighbour pixels, as depth peeling sees it,
// IRIS Sec. 5.1), and blended front to back with float accumulation. Screen-space derivatives of
// n_z and (s, t) (IRIS Eqs. 2-4) are the rasterizer's dFdx/dFdy stored at fill time — the one
// definition depth peeling (peel/peel_layer.frag) uses too, so the two renderers agree.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
#include "frame/surface_shading.glsl"
#include "frame/illustrative_shading.glsl"
#include "frame/sobel_silhouette.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
layout(std430, binding = BIND_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
uniform int uWidth;
uniform int uHeight;
uniform vec4 uBackground;
uniform vec2 uProjectionScale;  // (P[0][0], P[1][1]) of the perspective projection

float depthOf(uint f) { return uintBitsToFloat(sorted[fragWord(f, OFF_DEPTH)]); }
vec3 normalOf(uint f) { return decodeNormal(sorted[fragWord(f, TLAB_OFF_NORMAL)]); }
#ifdef TLAB_HAS_ST
vec2 stOf(uint f) {
  uint o = fragWord(f, TLAB_OFF_ST);
  return vec2(uintBitsToFloat(sorted[o]), uintBitsToFloat(sorted[o + 1u]));
}
#endif

// The view-space point of eye depth z seen through pixel centre xy.
vec3 viewPositionAt(vec2 xy, float z) {
  vec2 ndc = xy / vec2(uWidth, uHeight) * 2.0 - 1.0;
  return vec3(ndc / uProjectionScale * z, -z);
}

// The screen-space derivatives the fill pass stored (dFdx/dFdy, as depth peeling takes them).
void screenDerivatives(uint f, inout SurfaceSample s) {
#ifdef TLAB_HAS_NZ_GRADIENT
  uint o = fragWord(f, TLAB_OFF_NZ_GRADIENT);
  s.nzGradient = vec2(uintBitsToFloat(sorted[o]), uintBitsToFloat(sorted[o + 1u]));
#endif
#ifdef TLAB_HAS_ST_GRADIENT
  uint g = fragWord(f, TLAB_OFF_ST_GRADIENT);
  for (uint k = 0u; k < 4u; ++k) s.stGradient[k] = uintBitsToFloat(sorted[g + k]);
#endif
}

// Sobel on layer `layer` around pixel xy (IRIS Sec. 5.1).
float layerSilhouette(ivec2 xy, uint layer) {
  float depth[9];
  vec3 normal[9];
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int k = (dy + 1) * 3 + (dx + 1);
      ivec2 q = xy + ivec2(dx, dy);
      depth[k] = 0.0;
      normal[k] = vec3(0.0);
      if (q.x < 0 || q.y < 0 || q.x >= uWidth || q.y >= uHeight) continue;
      uint qp = uint(q.y * uWidth + q.x);
      if (pixelCount[qp] <= layer) continue;
      uint g = pixelHead[qp] + layer;
      bool context = isContext(sorted[fragWord(g, TLAB_OFF_IDS)] & 0xFFFFu);
      depth[k] = context ? -depthOf(g) : depthOf(g);
      normal[k] = normalOf(g);
    }
  return sobelStrength(depth, normal);
}

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uint(uWidth * uHeight)) return;
  uint n = pixelCount[pixel];
  uint base = pixelHead[pixel];
  ivec2 xy = ivec2(int(pixel % uint(uWidth)), int(pixel / uint(uWidth)));
  vec2 center = vec2(xy) + 0.5;
  vec3 c = vec3(0.0);
  float T = 1.0;  // remaining transmittance
  for (uint i = 0u; i < n && T > 0.0; ++i) {
    uint f = base + i;
    uint ids = sorted[fragWord(f, TLAB_OFF_IDS)];
    SurfaceSample s;
    s.viewPosition = viewPositionAt(center, depthOf(f));
    s.normal = normalOf(f);
    s.frontFacing = (ids & 0x80000000u) != 0u;
    s.object = ids & 0xFFFFu;
    s.layer = i;
    s.pixel = center;
#ifdef TLAB_HAS_ST
    s.st = stOf(f);
#else
    s.st = vec2(0.0);
#endif
    s.nzGradient = vec2(0.0);
    s.stGradient = vec4(0.0);
    screenDerivatives(f, s);
    vec4 ca = illustrate(s);
    if (SILHOUETTES != 0) ca = applySilhouette(ca, layerSilhouette(xy, i));
    c += T * ca.a * ca.rgb;
    T *= 1.0 - ca.a;
  }
  outColor[pixel] = vec4(c + T * uBackground.rgb, 1.0);
}
