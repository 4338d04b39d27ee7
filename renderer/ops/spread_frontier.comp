#version 450 core
// Eq. 9 spreading (Carnecky Sec. 5.4) on the frontier only: one step of
//   u'_i = max{u_i, max_{j ∈ N(i)} u_j − λ_u}   (free fragments; fixed ones keep their value)
// for exactly the fragments whose value can change, with the arithmetic of ops/diffuse_alpha.comp's
// fused spreading (u_j − λ, then max, which is exact in any order), so the fields are bit for bit
// those of full steps. Why only the frontier: a free fragment can change in step t only if one of its
// neighbours changed in step t − 1 (otherwise u_i^{t−1} ≥ u_j^{t−2} − λ = u_j^{t−1} − λ for every
// neighbour j already), and the links are mutual (the connect pass keeps only those), so the
// candidates of step t are the neighbours of the fragments step t − 1 changed. Step 1's "changed"
// list is the seeds: with every value ≥ 0 and λ ≥ 0, only a fragment above 0 can raise one.
// The step pushes instead of pulling: a candidate's new value is its old one raised to the best
// u_j − λ over its neighbours j that changed in step t − 1 (those that did not cannot raise it,
// see above), so each changed fragment offers u_j − λ to its free neighbours, and the largest
// offer wins by an atomic max on the value's bits (values are ≥ 0, where floats order like their
// bits): the pull of ops/diffuse_alpha.comp without reading every candidate's links and the
// values of all its neighbours.
// One pass a step, one invocation per fragment j that step t − 1 changed. The field's two copies
// take turns: step t reads the values of step t − 1 from one copy and raises the other, which
// holds the values of step t − 2 — all but those of the fragments step t − 1 changed, which are
// exactly the invocations: each first raises its own entry to its value of step t − 1, then makes
// its offers. Every write is an atomic max, so their order does not matter, and no value of the
// step is read before every offer is made (a Jacobi step, not Gauss-Seidel).
// Each raised neighbour is listed once per step for the next, by the offer that raises it first:
// the atomic max returns the entry it raised, and until this step raises f that entry is at most
// f's value after step t − 1, u[f] (the copy holds f's value of step t − 2 ≤ u[f], or u[f] itself
// once f's own invocation raised it), after it above (every offer that raises f exceeds u[f]). So
// no stamp per fragment and no second atomic per offer; and whether a step changed the field is
// whether its list is empty, which the host reads, so no flag either (issue #29: a CPU rasterizer
// runs atomics lane by lane; stamps and flag were 5 of the up to 12 an invocation ran).
// The host dispatches indirectly from the list header; invocations loop over lists longer than
// the dispatch limit.
#include "ops/field_bindings.glsl"
layout(local_size_x = 64) in;
// The values after step t − 1 (read only), and the other copy: those after step t − 2, raised
// to those after step t (bits of floats ≥ 0).
layout(std430, binding = BIND_BETA_IN) readonly buffer Field { float u[]; };
layout(std430, binding = BIND_BETA_OUT) buffer Next { uint next[]; };
#ifdef TLAB_FIELD_TEXELS
// The links, flags and values read as buffer textures where the GL allows that many texels (one
// fetch for all lanes, where a CPU rasterizer reads a storage buffer lane by lane): the same words.
uniform usamplerBuffer uLinks;   // RGBA32UI, a fragment's 4 links
uniform usamplerBuffer uFlags;   // R32UI
uniform samplerBuffer uValues;   // R32F, the copy u
uvec4 linksOf(uint f) { return texelFetch(uLinks, int(f)); }
uint flagsOf(uint f) { return texelFetch(uFlags, int(f)).x; }
float valueOf(uint f) { return texelFetch(uValues, int(f)).x; }
#else
layout(std430, binding = BIND_LINKS) readonly buffer Links { uvec4 links[]; };
layout(std430, binding = BIND_FLAGS) readonly buffer Flags { uint flags[]; };
uvec4 linksOf(uint f) { return links[f]; }
uint flagsOf(uint f) { return flags[f]; }
float valueOf(uint f) { return u[f]; }
#endif
FRONTIER_LIST(readonly, BIND_FRONTIER_IN, Previous, previous);
FRONTIER_LIST(, BIND_FRONTIER_OUT, Changed, changed);
uniform float uLambda;
uniform uint uFreeBit;

void main() {
  for (uint i = gl_GlobalInvocationID.x; i < previous.count; i += gl_NumWorkGroups.x * FRONTIER_GROUP) {
    uint j = previous.items[i];
    float value = valueOf(j);
    atomicMax(next[j], floatBitsToUint(value));  // (step 1's invocations, the seeds: already there)
    uvec4 around = linksOf(j);
    float offer = value - uLambda;  // Eq. 9's u_j − λ_u
    uint listed = 0u;  // bit k: neighbour k is this step's first to be raised
    for (int k = 0; k < 4; ++k) {
      uint f = around[k];
      if (f == NO_NEIGHBOR || (flagsOf(f) & uFreeBit) == 0u) continue;
      float before = valueOf(f);  // u[f], f's value after step t − 1
      if (!(offer > before)) continue;
      if (atomicMax(next[f], floatBitsToUint(offer)) <= floatBitsToUint(before)) listed |= 1u << uint(k);
    }
    // One atomic for the invocation's listed neighbours (every append to the list's count is an
    // atomic on one word, which the CPU rasterizer's threads pass between their caches).
    uint at = 0u;
    FRONTIER_RESERVE(changed, uint(bitCount(listed)), at);
    for (uint m = listed; m != 0u; m &= m - 1u, ++at) changed.items[at] = around[findLSB(m)];
  }
}
