#version 450 core
// One step of α diffusion on the fragment graph (Carnecky Eq. 7), one invocation per fragment,
// over the existing geodesic neighbours N(i) (Neumann at boundaries). Eq. 8's Laplacian in one of
// two readings, as the weight w of each neighbour:
//  normalised (default): Δα_i = (1/deg)·Σ_j (α_j − α_i) = mean of the neighbours − α_i: w = λ/deg;
//  sum:                   Δα_i = Σ_j (α_j − α_i): w = λ.
//  TLAB_JACOBI undefined: explicit step α' = α + b_α·w·Σ_j (α_j − α_i) (Eq. 8). It obeys the
//    maximum principle (new value a convex combination of old ones: no oscillation, stays in
//    [0, 1]) iff w·deg(i) ≤ 1: λ ≤ 1 normalised, λ ≤ 1/4 summed; the host sub-steps larger λ.
//  TLAB_JACOBI: one Jacobi sweep for the implicit step (1 + w·deg)α' − w·Σα'_j = α_old, which is
//    unconditionally stable; each sweep is again a convex combination.
//  TLAB_SKIP_ALPHA: α is uniform (Eq. 4) and diffusion cannot change it: only the fused spreading.
//  TLAB_FUSED_SPREAD: the same invocation also spreads β and γ by Eq. 9 (max-propagation), so a
//    step reads each fragment's links once (the first α dispatch of a step does this).
#include "frame/compute_index.glsl"
#include "ops/field_bindings.glsl"
layout(std430, binding = BIND_LINKS) readonly buffer Links { uvec4 links[]; };
#ifndef TLAB_SKIP_ALPHA
layout(std430, binding = BIND_ALPHA_IN) readonly buffer AlphaIn { float alphaIn[]; };
layout(std430, binding = BIND_ALPHA_OUT) writeonly buffer AlphaOut { float alphaOut[]; };
#endif
layout(std430, binding = BIND_FLAGS) readonly buffer Flags { uint flags[]; };
#ifdef TLAB_JACOBI
layout(std430, binding = BIND_ALPHA_OLD) readonly buffer AlphaOld { float alphaOld[]; };
#endif
#ifdef TLAB_FUSED_SPREAD
#ifdef TLAB_HAS_BETA
layout(std430, binding = BIND_BETA_IN) readonly buffer BetaIn { float betaIn[]; };
layout(std430, binding = BIND_BETA_OUT) writeonly buffer BetaOut { float betaOut[]; };
#endif
#ifdef TLAB_HAS_GAMMA
layout(std430, binding = BIND_GAMMA_IN) readonly buffer GammaIn { float gammaIn[]; };
layout(std430, binding = BIND_GAMMA_OUT) writeonly buffer GammaOut { float gammaOut[]; };
#endif
uniform float uLambdaBeta;
uniform float uLambdaGamma;
// Whether a field changed anywhere: a step that changes nothing is a fixed point, and the host
// stops spreading there.
layout(std430, binding = BIND_CHANGED) coherent buffer Changed { uint changed; };
void noteChange(bool differs, uint bit) {
  if (differs && (changed & bit) == 0u) atomicOr(changed, bit);
}
#endif
uniform uint uFragments;
uniform float uLambda;
uniform int uNormalized;  // 1: the normalised Laplacian, 0: the sum

void main() {
  uint f = linearInvocation();
  if (f >= uFragments) return;
  uvec4 l = links[f];
  uint fragFlags = flags[f];
#ifdef TLAB_FUSED_SPREAD
  // Eq. 9 on β and γ; fixed fragments (b = 0) keep their value.
#ifdef TLAB_HAS_BETA
  float b = betaIn[f];
  if ((fragFlags & FREE_BETA) != 0u)
    for (int k = 0; k < 4; ++k)
      if (l[k] != NO_NEIGHBOR) b = max(b, betaIn[l[k]] - uLambdaBeta);
  betaOut[f] = b;
  noteChange(b != betaIn[f], 2u);
#endif
#ifdef TLAB_HAS_GAMMA
  float g = gammaIn[f];
  if ((fragFlags & FREE_GAMMA) != 0u)
    for (int k = 0; k < 4; ++k)
      if (l[k] != NO_NEIGHBOR) g = max(g, gammaIn[l[k]] - uLambdaGamma);
  gammaOut[f] = g;
  noteChange(g != gammaIn[f], 4u);
#endif
#endif
#ifndef TLAB_SKIP_ALPHA
  float sum = 0.0;
  float degree = 0.0;
  for (int k = 0; k < 4; ++k)
    if (l[k] != NO_NEIGHBOR) {
      sum += alphaIn[l[k]];
      degree += 1.0;
    }
  bool free = (fragFlags & FREE_ALPHA) != 0u;
  float w = uNormalized == 1 ? (degree > 0.0 ? uLambda / degree : 0.0) : uLambda;
#ifdef TLAB_JACOBI
  alphaOut[f] = free ? (alphaOld[f] + w * sum) / (1.0 + w * degree) : alphaOld[f];
#else
  float a = alphaIn[f];
  alphaOut[f] = free ? a + w * (sum - degree * a) : a;  // Eq. 8
#endif
#endif
}
