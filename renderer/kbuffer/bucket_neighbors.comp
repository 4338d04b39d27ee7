#version 450 core
// Neighbour query of the bucketed k-buffer (seed 002, Sec. 5.1, Fig. 5), one invocation per
// pixel p: for each of its fragments f and each adjacent pixel q, the candidate g of q with
// minimum ε(f, g) = εn + εz among the fragments of f's shape, then the reverse check: g's best
// candidate among p's fragments of that shape must be f. Ties go to the lower index, exactly as
// kbuffer::bestCandidate on the CPU.
//  default: only the shape's bucket of q is scanned (B lookup, H(b) = b mod k);
//  TLAB_BRUTE_FORCE: every fragment of q is visited and filtered by shape (illustration buffer).
#include "buffer/fragment_layout.glsl"
#include "kbuffer/kbuffer_layout.glsl"
#include "buffer/compute_index.glsl"
layout(std430, binding = BIND_KB_Z) readonly buffer Z { uint z[]; };
layout(std430, binding = BIND_KB_TABLE) readonly buffer Table { uint table[]; };
layout(std430, binding = BIND_KB_DATA) readonly buffer Data { uvec2 data[]; };
layout(std430, binding = BIND_KB_LINKS) writeonly buffer Links { uint links[]; };
#include "kbuffer/bucket_lookup.glsl"
uniform int uWidth;
uniform int uHeight;

// This pixel's fragments, read once: shape-first keys, depths and view-facing normals.
uint ownKey[TLAB_K];
float ownDepth[TLAB_K];
vec3 ownNormal[TLAB_K];

// seed 002, Sec. 5.1: εn = 1 − n_i·n_j, εz = |z_i − z_j|², ε = εn + εz.
float continuity(vec3 ni, float zi, vec3 nj, float zj) {
  float dz = zi - zj;
  return (1.0 - dot(ni, nj)) + dz * dz;
}

// The best candidate (global slot) for a fragment (shape, n, z) among the fragments of that
// shape in the adjacent pixel whose slots start at qBase: memory reads of Z and D.
uint bestInNeighbor(uint shape, vec3 n, float depth, uint qBase) {
#ifdef TLAB_BRUTE_FORCE
  uint lo = qBase, hi = qBase + uint(TLAB_K);
#else
  uint bucket = findBucket(qBase, shape);
  if (bucket == KB_EMPTY) return KB_NO_NEIGHBOR;
  uint lo = qBase + bucketFirst(bucket), hi = qBase + bucketLast(bucket) + 1u;
#endif
  uint best = KB_NO_NEIGHBOR;
  float bestEps = 1.0 / 0.0;
  for (uint j = lo; j < hi; ++j) {
    uint key = z[j];
#ifdef TLAB_BRUTE_FORCE
    if (key == KB_EMPTY) break;
    if (shapeOfShapeFirst(key) != shape) continue;
#endif
    float e = continuity(n, depth, decodeNormal(data[j].y), depthOfShapeFirst(key));
    if (e < bestEps) {
      bestEps = e;
      best = j;
    }
  }
  return best;
}

// The reverse check's search: the best of this pixel's own fragments [lo, hi) of `shape`.
uint bestInOwn(uint shape, vec3 n, float depth, uint lo, uint hi) {
  uint best = KB_NO_NEIGHBOR;
  float bestEps = 1.0 / 0.0;
  for (uint i = lo; i < hi; ++i) {
#ifdef TLAB_BRUTE_FORCE
    if (shapeOfShapeFirst(ownKey[i]) != shape) continue;
#endif
    float e = continuity(n, depth, ownNormal[i], ownDepth[i]);
    if (e < bestEps) {
      bestEps = e;
      best = i;
    }
  }
  return best;
}

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uint(uWidth * uHeight)) return;
  ivec2 xy = ivec2(int(pixel % uint(uWidth)), int(pixel / uint(uWidth)));
  uint base = slotOf(pixel, 0u);
  uint n = 0u;
  for (; n < uint(TLAB_K); ++n) {
    uint key = z[base + n];
    if (key == KB_EMPTY) break;
    ownKey[n] = key;
    ownDepth[n] = depthOfShapeFirst(key);
    ownNormal[n] = decodeNormal(data[base + n].y);
  }
  for (uint layer = 0u; layer < n; ++layer) {
    uint shape = shapeOfShapeFirst(ownKey[layer]);
#ifdef TLAB_BRUTE_FORCE
    uint ownLo = 0u, ownHi = n;
#else
    uint ownBucket = findBucket(base, shape);
    uint ownLo = bucketFirst(ownBucket), ownHi = bucketLast(ownBucket) + 1u;
#endif
    uint link = 0u;
    for (int d = 0; d < 4; ++d) {
      ivec2 q = xy + kDirections[d];
      uint layerInQ = KB_NO_LINK;
      if (q.x >= 0 && q.y >= 0 && q.x < uWidth && q.y < uHeight) {
        uint qBase = slotOf(uint(q.y * uWidth + q.x), 0u);
        uint g = bestInNeighbor(shape, ownNormal[layer], ownDepth[layer], qBase);
        // Fig. 5: the reverse check, g's best candidate among this pixel's fragments.
        if (g != KB_NO_NEIGHBOR &&
            bestInOwn(shape, decodeNormal(data[g].y), depthOfShapeFirst(z[g]), ownLo, ownHi) == layer)
          layerInQ = g - qBase;
      }
      link |= layerInQ << (8 * d);
    }
    links[base + layer] = link;
  }
}
