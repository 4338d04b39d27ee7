#version 450 core
// Eq. 9 spreading (Carnecky Sec. 5.4) on the frontier only: one step of
//   u'_i = max{u_i, max_{j ∈ N(i)} u_j − λ_u}   (free fragments; fixed ones keep their value)
// for exactly the fragments whose value can change, each evaluated with the same arithmetic in
// the same order as ops/diffuse_alpha.comp's fused spreading, so the fields are bit for bit those
// of full steps. Why only the frontier: a free fragment can change in step t only if one of its
// neighbours changed in step t − 1 (otherwise u_i^{t−1} ≥ u_j^{t−2} − λ = u_j^{t−1} − λ for every
// neighbour j already), and the links are mutual (the connect pass keeps only those), so the
// candidates of step t are the neighbours of the fragments step t − 1 changed. Step 1's "changed"
// list is the seeds: with every value ≥ 0 and λ ≥ 0, only a fragment above 0 can raise one.
//  (default) one invocation per fragment of the input list: claims each free neighbour once per
//    step (the stamp), evaluates it on the step's old values, and lists it with its new value
//    when that differs;
//  TLAB_FRONTIER_APPLY: writes the listed new values (a pass of their own, so that every
//    evaluation of a step reads the values before it: a Jacobi step, not Gauss-Seidel).
// The host dispatches both indirectly from the list headers; invocations loop over lists longer
// than the dispatch limit.
#include "ops/field_bindings.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = BIND_BETA_IN) buffer Field { float u[]; };
layout(std430, binding = BIND_FRONTIER_VALUES) buffer Values { float values[]; };
#ifdef TLAB_FRONTIER_APPLY
FRONTIER_LIST(readonly, BIND_FRONTIER_OUT, Changed, changed);
// Whether the field changed since the host last looked (uFreeBit), as the full steps record it.
layout(std430, binding = BIND_CHANGED) buffer Moved { uint moved; };
uniform uint uFreeBit;

void main() {
  if (gl_GlobalInvocationID.x == 0u && changed.count > 0u) atomicOr(moved, uFreeBit);
  for (uint i = gl_GlobalInvocationID.x; i < changed.count; i += gl_NumWorkGroups.x * FRONTIER_GROUP)
    u[changed.items[i]] = values[i];
}
#else
#ifdef TLAB_FIELD_TEXELS
// The links, flags and values read as buffer textures where the GL allows that many texels (one
// fetch for all lanes, where a CPU rasterizer reads a storage buffer lane by lane): the same words.
uniform usamplerBuffer uLinks;   // RGBA32UI, a fragment's 4 links
uniform usamplerBuffer uFlags;   // R32UI
uniform samplerBuffer uValues;   // R32F, the field u (TLAB_FRONTIER_APPLY writes it between steps)
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
layout(std430, binding = BIND_STAMPS) buffer Stamps { uint stamps[]; };
FRONTIER_LIST(readonly, BIND_FRONTIER_IN, Previous, previous);
FRONTIER_LIST(, BIND_FRONTIER_OUT, Changed, changed);
uniform float uLambda;
uniform uint uFreeBit;
uniform uint uTag;  // this step's stamp: no fragment holds it before the step

void main() {
  for (uint i = gl_GlobalInvocationID.x; i < previous.count; i += gl_NumWorkGroups.x * FRONTIER_GROUP) {
    uvec4 around = linksOf(previous.items[i]);
    uint moved = 0u;  // bit k: neighbour k changes, to news[k]
    vec4 news = vec4(0.0);
    for (int k = 0; k < 4; ++k) {
      uint f = around[k];
      if (f == NO_NEIGHBOR || (flagsOf(f) & uFreeBit) == 0u || atomicExchange(stamps[f], uTag) == uTag)
        continue;
      // Eq. 9, as ops/diffuse_alpha.comp computes it.
      uvec4 l = linksOf(f);
      float old = valueOf(f), b = old;
      for (int m = 0; m < 4; ++m)
        if (l[m] != NO_NEIGHBOR) b = max(b, valueOf(l[m]) - uLambda);
      news[k] = b;
      if (b != old) moved |= 1u << uint(k);
    }
    // One atomic for the invocation's changed neighbours (every append to the list's count is an
    // atomic on one word, which the CPU rasterizer's threads pass between their caches).
    uint at = 0u;
    FRONTIER_RESERVE(changed, uint(bitCount(moved)), at);
    for (uint m = moved; m != 0u; m &= m - 1u, ++at) {
      int k = findLSB(m);
      changed.items[at] = around[k];
      values[at] = news[k];
    }
  }
}
#endif
