#version 450 core
// Neighbour query of the bucketed k-buffer (seed 002, Sec. 5.1, Fig. 5), one invocation per
// pixel p: for each of its fragments f and each adjacent pixel q, the candidate g of q with
// minimum ε(f, g) = εn + εz among the fragments of f's shape, then the reverse check: g's best
// candidate among p's fragments of that shape must be f. Ties go to the lower index, exactly as
// kbuffer::bestCandidate on the CPU.
//  default: only the shape's bucket of q is scanned (B lookup, H(b) = b mod k);
//  TLAB_BRUTE_FORCE: every fragment of q is visited and filtered by shape (illustration buffer).
#include "frame/fragment_layout.glsl"
#include "kbuffer/kbuffer_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_KB_Z) readonly buffer Z { uint z[]; };
layout(std430, binding = BIND_KB_TABLE) readonly buffer Table { uint table[]; };
layout(std430, binding = BIND_KB_DATA) readonly buffer Data { uvec2 data[]; };
layout(std430, binding = BIND_KB_LINKS) writeonly buffer Links { uint links[]; };
#include "kbuffer/bucket_lookup.glsl"
uniform int uWidth;
uniform int uHeight;

// seed 002, Sec. 5.1: εn = 1 − n_i·n_j, εz = |z_i − z_j|², ε = εn + εz.
// `precise`: evaluated as written. NVIDIA's compiler (H200, driver 580) otherwise computed it as
// (1 + εz) − n_i·n_j, where an εz below 2⁻²⁴ vanishes: two quads of one object 11 or fewer 16-bit
// depth steps apart then tied, and the farther one lost every link (issue #29's GPU test run).
float continuity(vec3 ni, float zi, vec3 nj, float zj) {
  precise float dz = zi - zj;
  precise float e = (1.0 - dot(ni, nj)) + dz * dz;
  return e;
}

// The range of slots to scan for a fragment of `shape` in the pixel whose slots start at
// `base`: the shape's bucket, or (brute force) the whole list. Empty when there is no bucket.
uvec2 candidateRange(uint base, uint shape) {
#ifdef TLAB_BRUTE_FORCE
  return uvec2(base, base + uint(TLAB_K));
#else
  uint bucket = findBucket(base, shape);
  if (bucket == KB_EMPTY) return uvec2(base, base);
  return uvec2(base + bucketFirst(bucket), base + bucketLast(bucket) + 1u);
#endif
}

// The best candidate (global slot) for a fragment (shape, n, z) in `range`, read from Z and D
// as the illustration buffer reads its lists; its normal and depth are returned too.
uint bestCandidate(uint shape, vec3 n, float depth, uvec2 range, out vec3 bestNormal, out float bestDepth) {
  uint best = KB_NO_NEIGHBOR;
  float bestEps = 1.0 / 0.0;
  for (uint j = range.x; j < range.y; ++j) {
    uint key = z[j];
#ifdef TLAB_BRUTE_FORCE
    if (key == KB_EMPTY) break;
    if (shapeOfShapeFirst(key) != shape) continue;  // shape filter: ε = ∞ across shapes
#endif
    vec3 nj = decodeNormal(data[j].y);
    float zj = depthOfShapeFirst(key);
    float e = continuity(n, depth, nj, zj);
    if (e < bestEps) {
      bestEps = e;
      best = j;
      bestNormal = nj;
      bestDepth = zj;
    }
  }
  return best;
}

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uint(uWidth * uHeight)) return;
  ivec2 xy = ivec2(int(pixel % uint(uWidth)), int(pixel / uint(uWidth)));
  uint base = slotOf(pixel, 0u);
  for (uint layer = 0u; layer < uint(TLAB_K); ++layer) {
    uint f = base + layer;
    uint key = z[f];
    if (key == KB_EMPTY) break;
    uint shape = shapeOfShapeFirst(key);
    vec3 n = decodeNormal(data[f].y);
    float depth = depthOfShapeFirst(key);
    uvec2 ownRange = candidateRange(base, shape);
    uint link = 0u;
    for (int d = 0; d < 4; ++d) {
      ivec2 q = xy + kDirections[d];
      uint layerInQ = KB_NO_LINK;
      if (q.x >= 0 && q.y >= 0 && q.x < uWidth && q.y < uHeight) {
        uint qBase = slotOf(uint(q.y * uWidth + q.x), 0u);
        vec3 gNormal, unusedNormal;
        float gDepth, unusedDepth;
        uint g = bestCandidate(shape, n, depth, candidateRange(qBase, shape), gNormal, gDepth);
        // Fig. 5: the reverse check, g's best candidate among this pixel's fragments must be f.
        if (g != KB_NO_NEIGHBOR && bestCandidate(shape, gNormal, gDepth, ownRange, unusedNormal, unusedDepth) == f)
          layerInQ = g - qBase;
      }
      link |= layerInQ << (8 * d);
    }
    links[f] = link;
  }
}
