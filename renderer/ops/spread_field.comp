#version 450 core
// Spreads a boundary-seeded field u ∈ {β, γ} (Carnecky Sec. 5.4), one invocation per fragment:
//  TLAB_SPREAD_MAX: u' = max{u, max_{j ∈ N(i)} u_j − λ_u} (Eq. 9): 1 − u grows ~ linearly with
//    the graph distance to the nearest boundary.
//  otherwise: the explicit diffusion step of Eq. 8 with λ_u (the host sub-steps λ_u > 1/4).
// Fragments fixed by a boundary condition (b_u = 0) keep their value.
#include "frame/compute_index.glsl"
#include "ops/field_bindings.glsl"
layout(std430, binding = BIND_LINKS) readonly buffer Links { uvec4 links[]; };
layout(std430, binding = BIND_BETA_IN) readonly buffer FieldIn { float u[]; };
layout(std430, binding = BIND_BETA_OUT) writeonly buffer FieldOut { float uOut[]; };
layout(std430, binding = BIND_FLAGS) readonly buffer Flags { uint flags[]; };
uniform uint uFragments;
uniform float uLambda;
uniform uint uFreeBit;

void main() {
  uint f = linearInvocation();
  if (f >= uFragments) return;
  float value = u[f];
  if ((flags[f] & uFreeBit) == 0u) {
    uOut[f] = value;
    return;
  }
  uvec4 l = links[f];
#ifdef TLAB_SPREAD_MAX
  float best = value;
  for (int k = 0; k < 4; ++k)
    if (l[k] != NO_NEIGHBOR) best = max(best, u[l[k]] - uLambda);
  uOut[f] = best;
#else
  float sum = 0.0, degree = 0.0;
  for (int k = 0; k < 4; ++k)
    if (l[k] != NO_NEIGHBOR) {
      sum += u[l[k]];
      degree += 1.0;
    }
  uOut[f] = value + uLambda * (sum - degree * value);
#endif
}
