#version 450 core
// Sort pass (Carnecky Sec. 4.3): each pixel's fragments, front to back, into the contiguous
// block [pixelHead, pixelHead + pixelCount) of the sorted buffer (fragData2). Ties in depth are
// broken by the global triangle index, so the order never depends on thread scheduling.
// TLAB_LINKED_LIST: the unsorted fragments are a linked list (Alg. 1) instead of a block.
// TLAB_SLOTS: they sit in uSlots slots (buffer/fill_slots.frag): the i-th at i * uPixels + pixel.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_PIXEL_CURSOR) readonly buffer ListHead { uint listHead[]; };
layout(std430, binding = BIND_LIST_NEXT) readonly buffer ListNext { uint listNext[]; };
layout(std430, binding = BIND_FRAGS_UNSORTED) readonly buffer Frags { uint frags[]; };
layout(std430, binding = BIND_FRAGS_SORTED) writeonly buffer Sorted { uint sorted[]; };
// Per fragment: (depth bits, source index). Positive floats order like their bit patterns, so
// the keys compare as integers, and each pixel's keys sit together in memory.
layout(std430, binding = BIND_ORDER) buffer Order { uvec2 order[]; };
uniform uint uPixels;

bool before(uvec2 a, uvec2 b) {
  if (a.x != b.x) return a.x < b.x;
  return frags[fragWord(a.y, OFF_PRIM)] < frags[fragWord(b.y, OFF_PRIM)];
}

uvec2 keyOf(uint src) { return uvec2(frags[fragWord(src, OFF_DEPTH)], src); }

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uPixels) return;
  uint n = pixelCount[pixel];
  if (n == 0u) return;
  uint base = pixelHead[pixel];
#ifdef TLAB_LINKED_LIST
  uint f = listHead[pixel];
  for (uint i = 0u; i < n; ++i) {
    order[base + i] = keyOf(f);
    f = listNext[f];
  }
#elif defined(TLAB_SLOTS)
  for (uint i = 0u; i < n; ++i) order[base + i] = keyOf(i * uPixels + pixel);
#else
  for (uint i = 0u; i < n; ++i) order[base + i] = keyOf(base + i);
#endif
  // Insertion sort of the indices; lists are short except where a surface is seen edge-on.
  for (uint i = 1u; i < n; ++i) {
    uvec2 key = order[base + i];
    uint j = i;
    while (j > 0u && before(key, order[base + j - 1u])) {
      order[base + j] = order[base + j - 1u];
      --j;
    }
    order[base + j] = key;
  }
  for (uint i = 0u; i < n; ++i) {
    uint src = order[base + i].y;
    for (uint w = 0u; w < uint(TLAB_STRIDE); ++w) sorted[fragWord(base + i, w)] = frags[fragWord(src, w)];
  }
}
