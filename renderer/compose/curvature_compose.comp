#version 450 core
// Blending of the bucketed k-buffer (seed 002, Sec. 5.2): the pixel's fragments in depth order,
// c ← c + T·α·c_i, T ← T·(1 − α), then c ← c + T·c_background, with
//  TLAB_STYLIZATION 0: c_i the shaded colour, α constant;
//                   1: c_i × 2·tf1(κ) (mean-curvature shading), α constant;
//                   2: c_i × 2·tf1(κ), α = tf2(|κ|, depth) (mean-curvature transparency).
#include "kbuffer/kbuffer_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_KB_Z) readonly buffer Z { uint z[]; };
layout(std430, binding = BIND_KB_DATA) readonly buffer Data { uvec2 data[]; };
#if TLAB_STYLIZATION > 0
layout(std430, binding = BIND_KB_CURVATURE) readonly buffer Curvature { float kappa[]; };
#endif
#define TF1_SAMPLES 256
#define TF2_SAMPLES 128
layout(std430, binding = BIND_KB_TRANSFER) readonly buffer Transfer { vec4 tf1[TF1_SAMPLES]; float tf2[]; };
layout(std430, binding = BIND_KB_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
uniform uint uPixels;
uniform vec4 uBackground;
uniform float uAlpha;

float depthOf(uint key) {
#ifdef TLAB_BUCKETS
  return depthOfShapeFirst(key);
#else
  return depthOfDepthFirst(key);
#endif
}

vec3 shadingTf(float k) {
  float x = (clamp(k, -1.0, 1.0) + 1.0) * 0.5 * float(TF1_SAMPLES - 1);
  int i = min(int(x), TF1_SAMPLES - 2);
  return mix(tf1[i].rgb, tf1[i + 1].rgb, x - float(i));
}

float opacityTf(float absK, float depth) {
  float y = clamp(depth, 0.0, 1.0) * float(TF2_SAMPLES - 1), x = clamp(absK, 0.0, 1.0) * float(TF2_SAMPLES - 1);
  int i = min(int(y), TF2_SAMPLES - 2), j = min(int(x), TF2_SAMPLES - 2);
  float ty = y - float(i), tx = x - float(j);
  float a = mix(tf2[i * TF2_SAMPLES + j], tf2[i * TF2_SAMPLES + j + 1], tx);
  float b = mix(tf2[(i + 1) * TF2_SAMPLES + j], tf2[(i + 1) * TF2_SAMPLES + j + 1], tx);
  return mix(a, b, ty);
}

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uPixels) return;
  uint base = slotOf(pixel, 0u);
  // The pixel's slots ordered by depth (Z is in shape order after the bucket reorder).
  uint order[TLAB_K];
  float depth[TLAB_K];
  uint n = 0u;
  for (uint i = 0u; i < uint(TLAB_K); ++i) {
    uint key = z[base + i];
    if (key == KB_EMPTY) break;
    float d = depthOf(key);
    uint j = n;
    while (j > 0u && depth[j - 1u] > d) {
      depth[j] = depth[j - 1u];
      order[j] = order[j - 1u];
      --j;
    }
    depth[j] = d;
    order[j] = base + i;
    ++n;
  }
  vec3 c = vec3(0.0);
  float T = 1.0;
  for (uint i = 0u; i < n; ++i) {
    uint f = order[i];
    vec3 ci = unpackUnorm4x8(data[f].x).rgb;
    float a = uAlpha;
#if TLAB_STYLIZATION > 0
    float k = kappa[f];
    ci = min(ci * 2.0 * shadingTf(k), vec3(1.0));
#endif
#if TLAB_STYLIZATION == 2
    a = opacityTf(abs(k), depth[i]);
#endif
    c += T * a * ci;
    T *= 1.0 - a;
  }
  outColor[pixel] = vec4(c + T * uBackground.rgb, 1.0);
}
