#version 450 core
// Front-to-back alpha blending of each pixel's sorted fragment list with float accumulation:
//   c ← c + T·α·c_i,  T ← T·(1 − α),  and finally c ← c + T·c_background.
// The per-fragment opacity comes from TLAB_ALPHA_SOURCE: 0 = the uniform uAlpha (style
// `constant`); later styles provide their own per-fragment α.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
layout(std430, binding = BIND_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
uniform uint uPixels;
uniform vec4 uBackground;
uniform float uAlpha;

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uPixels) return;
  uint n = pixelCount[pixel];
  uint base = pixelHead[pixel];
  vec3 c = vec3(0.0);
  float T = 1.0;  // remaining transmittance
  for (uint i = 0u; i < n; ++i) {
    vec3 ci = unpackUnorm4x8(sorted[fragWord(base + i, TLAB_OFF_COLOR)]).rgb;
    float a = uAlpha;
    c += T * a * ci;
    T *= 1.0 - a;
  }
  outColor[pixel] = vec4(c + T * uBackground.rgb, 1.0);
}
