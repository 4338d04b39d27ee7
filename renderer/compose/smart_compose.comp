#version 450 core
// Smart transparency compositing (Carnecky Sec. 5.5, Alg. 3), one invocation per pixel that holds
// a fragment (the host cleared the others to the background), front to back, after the profile
// modifiers of Eqs. 10-11 are applied to β and γ:
//   α̂_i = (1 − γ_i)·(α_i + (1 − α_i)·β_i),  c ← c + T·α̂_i·c_i,  T ← T·(1 − α̂_i),
//   and finally c ← c + T·c_background.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
#include "frame/covered_pixels.glsl"
#include "ops/field_bindings.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
layout(std430, binding = BIND_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
layout(std430, binding = BIND_ALPHA_IN) readonly buffer Alpha { float alpha[]; };
#ifdef TLAB_HAS_BETA
layout(std430, binding = BIND_BETA_IN) readonly buffer Beta { float beta[]; };
#endif
#ifdef TLAB_HAS_GAMMA
layout(std430, binding = BIND_GAMMA_IN) readonly buffer Gamma { float gamma[]; };
#endif
uniform vec4 uBackground;
// TLAB_MODIFIER: 0 none, 1 exp (Eq. 10), 2 pow (Eq. 11), a define rather than a uniform: llvmpipe
// evaluates both sides of an `if` under a mask, so with a uniform every fragment also computed
// the modifier it did not use.
uniform float uP;

float modifyProfile(float u) {
  u = clamp(u, 0.0, 1.0);
#if TLAB_MODIFIER == 1
  return (exp(-uP * (1.0 - u)) - exp(-uP)) / (1.0 - exp(-uP));  // Eq. 10
#elif TLAB_MODIFIER == 2
  return pow(u, uP);  // Eq. 11
#else
  return u;
#endif
}

void main() {
  uint pixel;
  if (!coveredInvocation(pixel)) return;
  uint n = pixelCount[pixel];
  uint base = pixelHead[pixel];
  vec3 c = vec3(0.0);
  float T = 1.0;
  for (uint i = 0u; i < n; ++i) {
    uint f = base + i;
    float a = clamp(alpha[f], 0.0, 1.0);
    float b = 0.0, g = 0.0;
#ifdef TLAB_HAS_BETA
    b = modifyProfile(beta[f]);
#endif
#ifdef TLAB_HAS_GAMMA
    g = modifyProfile(gamma[f]);
#endif
    float aHat = (1.0 - g) * (a + (1.0 - a) * b);
    vec3 ci = unpackUnorm4x8(sorted[fragWord(f, TLAB_OFF_COLOR)]).rgb;
    c += T * aHat * ci;
    T *= 1.0 - aHat;
  }
  outColor[pixel] = vec4(c + T * uBackground.rgb, 1.0);
}
