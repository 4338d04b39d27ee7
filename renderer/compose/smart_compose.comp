#version 450 core
// Smart transparency compositing (Carnecky Sec. 5.5, Alg. 3), one invocation per pixel that holds
// a fragment (the host cleared the others to the background), front to back, after the profile
// modifiers of Eqs. 10-11 are applied to β and γ:
//   α̂_i = (1 − γ_i)·(α_i + (1 − α_i)·β_i),  c ← c + T·α̂_i·c_i,  T ← T·(1 − α̂_i),
//   and finally c ← c + T·c_background.
// TLAB_HAS_BETA / TLAB_HAS_GAMMA only where that field may be above 0 somewhere (the host leaves
// out a field that is 0 everywhere: β_i = 0 gives the same α̂_i, bit for bit); TLAB_UNIFORM_ALPHA
// where α is s everywhere (Eq. 4): then no field is read but the colour (issue #29).
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
#include "frame/covered_pixels.glsl"
#include "ops/field_bindings.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
#ifdef TLAB_COLOR_PLANE
// The colour words alone, in the sorted order (buffer/sort.comp): 4 contiguous bytes a fragment
// where one word of each record touched every record's cache line.
layout(std430, binding = BIND_COLOR_PLANE) readonly buffer ColorPlane { uint colorPlane[]; };
uint colorWord(uint f) { return colorPlane[f]; }
#else
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
uint colorWord(uint f) { return sorted[fragWord(f, TLAB_OFF_COLOR)]; }
#endif
layout(std430, binding = BIND_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
#ifdef TLAB_UNIFORM_ALPHA
uniform float uS;  // one α everywhere (Eq. 4: s), which the connect pass did not store for each fragment
#else
layout(std430, binding = BIND_ALPHA_IN) readonly buffer Alpha { float alpha[]; };
#endif
#ifdef TLAB_HAS_BETA
layout(std430, binding = BIND_BETA_IN) readonly buffer Beta { float beta[]; };
#endif
#ifdef TLAB_HAS_GAMMA
layout(std430, binding = BIND_GAMMA_IN) readonly buffer Gamma { float gamma[]; };
#endif
uniform vec4 uBackground;
#include "compose/profile_modifier.glsl"

void main() {
  uint pixel;
  if (!coveredInvocation(pixel)) return;
  uint n = pixelCount[pixel];
  uint base = pixelHead[pixel];
  vec3 c = vec3(0.0);
  float T = 1.0;
  for (uint i = 0u; i < n; ++i) {
    uint f = base + i;
#ifdef TLAB_UNIFORM_ALPHA
    float a = clamp(uS, 0.0, 1.0);
#else
    float a = clamp(alpha[f], 0.0, 1.0);
#endif
    float b = 0.0, g = 0.0;
#ifdef TLAB_HAS_BETA
    b = modifyProfile(beta[f]);
#endif
#ifdef TLAB_HAS_GAMMA
    g = modifyProfile(gamma[f]);
#endif
    float aHat = (1.0 - g) * (a + (1.0 - a) * b);
    vec3 ci = unpackUnorm4x8(colorWord(f)).rgb;
    c += T * aHat * ci;
    T *= 1.0 - aHat;
  }
  outColor[pixel] = vec4(c + T * uBackground.rgb, 1.0);
}
