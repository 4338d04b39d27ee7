#version 450 core
// Dynamic transparency compositing (Elmqvist et al., seed 004, Secs. V.1-V.4) on the
// illustration buffer. The frame buffer of the paper holds a colour and an alpha A that starts at
// 1; surfaces are drawn back to front (compose/dynamic_surfaces.glsl) and blended with A:
//     c ← A·c_s + (1 − A)·c                                          (Sec. V.3, step 2)
// and drawing a target multiplies its alpha mask into A (Sec. V.3, target step 2): α_T over the
// target, so every surface drawn after it — in front of it — is see-through. Around targets the
// low-resolution mask (ops/alpha_mask, sampled bilinearly, Alg. 2 line 10) adds the border
// gradient α_B for surfaces in front of the target the border belongs to.
// Stacking: "multiply" is the paper (k occluders in front of a target leave it (1 − α_T)^k);
// "shared" gives a run of k surfaces with the same A the opacity one surface has in the paper,
// β = 1 − (1 − A)^(1/k), so a target keeps the weight 1 − α_T behind any number of distractors
// (R2, unlimited depth).
// Active mode: everything above happens only inside the lens (a disc at uLens.xy with radius
// uLens.z pixels, 1 pixel anti-aliased edge); outside it the nearest surface is drawn opaque.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
#include "frame/surface_shading.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
layout(std430, binding = BIND_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
layout(std430, binding = 13) readonly buffer MaskAlpha { float maskAlpha[]; };
layout(std430, binding = 14) readonly buffer MaskDepth { float maskDepth[]; };
uniform int uWidth;
uniform int uHeight;
uniform vec4 uBackground;
uniform int uMaskSize;
uniform float uAlphaTarget;  // α_T
uniform int uSharedStacking;
uniform vec4 uLens;          // x, y (GL pixels), radius (pixels), 1: active mode
#include "compose/dynamic_surfaces.glsl"

vec3 colorOf(uint f) { return unpackUnorm4x8(sorted[fragWord(f, TLAB_OFF_COLOR)]).rgb; }

// The mask at pixel p: bilinear α, and the farthest target depth among the four cells.
vec2 sampleMask(vec2 p) {
  vec2 uv = p / vec2(uWidth, uHeight) * float(uMaskSize) - 0.5;
  ivec2 c0 = ivec2(floor(uv));
  vec2 t = uv - vec2(c0);
  float a[4];
  float depth = 0.0;
  for (int i = 0; i < 4; ++i) {
    ivec2 c = clamp(c0 + ivec2(i & 1, i >> 1), ivec2(0), ivec2(uMaskSize - 1));
    int cell = c.y * uMaskSize + c.x;
    a[i] = maskAlpha[cell];
    if (a[i] < 1.0) depth = max(depth, maskDepth[cell]);
  }
  return vec2(mix(mix(a[0], a[1], t.x), mix(a[2], a[3], t.x), t.y), depth);
}

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uint(uWidth * uHeight)) return;
  if (pixelCount[pixel] == 0u) {
    outColor[pixel] = vec4(uBackground.rgb, 1.0);
    return;
  }
  collectSurfaces(pixelHead[pixel], pixelCount[pixel]);
  vec2 p = vec2(pixel % uint(uWidth), pixel / uint(uWidth)) + 0.5;
  float inLens = uLens.w > 0.5 ? clamp(uLens.z - distance(p, uLens.xy) + 0.5, 0.0, 1.0) : 1.0;
  float alphaT = mix(1.0, uAlphaTarget, inLens);

  bool onTarget = false;
  for (int k = 0; k < gSurfaceCount; ++k) onTarget = onTarget || isTarget(gSurface[k]);
  // On a target its own surface places the mask exactly (Alg. 2 line 11); elsewhere the border.
  vec2 border = onTarget ? vec2(1.0, 0.0) : sampleMask(p);
  float alphaB = mix(1.0, border.x, inLens);

  // A before each surface is drawn, back to front, and the runs between changes of A.
  float opacity[MAX_SURFACES];
  int runOf[MAX_SURFACES];
  int runLength[MAX_SURFACES + 2];
  for (int r = 0; r < MAX_SURFACES + 2; ++r) runLength[r] = 0;
  float A = 1.0;
  int run = 0;
  bool borderDone = alphaB >= 1.0;
  for (int k = 0; k < gSurfaceCount; ++k) {
    uint f = gSurface[k];
    if (!borderDone && border.y > depthOf(f)) {
      A *= alphaB;
      borderDone = true;
      run = min(run + 1, MAX_SURFACES + 1);
    }
    opacity[k] = (k == 0 && gTruncated) ? 1.0 : A;
    runOf[k] = run;
    runLength[run] += 1;
    if ((k == 0 && gTruncated) || isTarget(f)) {
      if (isTarget(f)) A *= alphaT;
      run = min(run + 1, MAX_SURFACES + 1);
    }
  }
  vec3 c = uBackground.rgb;
  for (int k = 0; k < gSurfaceCount; ++k) {
    float a = opacity[k];
    float beta = uSharedStacking != 0 ? 1.0 - pow(1.0 - a, 1.0 / float(runLength[runOf[k]])) : a;
    c = beta * colorOf(gSurface[k]) + (1.0 - beta) * c;
  }
  outColor[pixel] = vec4(c, 1.0);
}
