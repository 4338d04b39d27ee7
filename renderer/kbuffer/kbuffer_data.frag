#version 450 core
// Data pass of the bucketed k-buffer (seed 002, Sec. 4.1 "Data storage", Fig. 4): each fragment
// looks up its shape's bucket in B, finds its own index inside the bucket's range by binary
// search on the key and stores its shaded colour and packed normal in D at that index;
// fragments not among the k nearest find no index and are dropped. Without TLAB_BUCKETS the
// search spans the pixel's whole depth-ordered list (a plain dual-pass k-buffer).
#include "frame/fragment_layout.glsl"
#include "frame/surface_shading.glsl"
#include "kbuffer/kbuffer_layout.glsl"
layout(std430, binding = BIND_KB_Z) readonly buffer Z { uint z[]; };
layout(std430, binding = BIND_KB_TABLE) readonly buffer Table { uint table[]; };
layout(std430, binding = BIND_KB_DATA) writeonly buffer Data { uvec2 data[]; };
#include "kbuffer/kbuffer_fragment.glsl"
#include "kbuffer/bucket_lookup.glsl"
in vec3 vViewNormal;

// Lower bound of `key` in z[lo, hi); returns hi when absent.
uint binarySearch(uint lo, uint hi, uint key) {
  uint end = hi;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (z[mid] < key) lo = mid + 1u;
    else hi = mid;
  }
  return (lo < end && z[lo] == key) ? lo : end;
}

void main() {
  uint base = slotOf(currentPixel(), 0u);
  uint key = packDepthFirst(currentDepth16(), currentShape());
#ifdef TLAB_BUCKETS
  uint bucket = findBucket(base, currentShape());
  if (bucket == KB_EMPTY) return;
  uint lo = base + bucketFirst(bucket), hi = base + bucketLast(bucket) + 1u;
  uint at = binarySearch(lo, hi, swapHalves(key));
#else
  uint lo = base, hi = base + uint(TLAB_K);
  uint at = binarySearch(lo, hi, key);
#endif
  if (at == hi) return;  // not among the k nearest
  vec3 color = shadeSurface(vObject, gl_FrontFacing, vViewNormal, vViewPosition);
  vec3 facing = normalize(vViewNormal) * (gl_FrontFacing ? 1.0 : -1.0);  // towards the viewer
  data[at] = uvec2(packUnorm4x8(vec4(color, 1.0)), encodeNormal(facing));
}
