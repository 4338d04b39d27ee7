#version 450 core
// Sort pass (Carnecky Sec. 4.3): each pixel's fragments, front to back, into the contiguous
// block [pixelHead, pixelHead + pixelCount) of the sorted buffer (fragData2). Ties in depth are
// broken by the global triangle index, then by the order the fragments arrived in, so the order
// never depends on thread scheduling.
// TLAB_LINKED_LIST: the unsorted fragments are a linked list (Alg. 1) instead of a block.
// TLAB_SLOTS: they sit in uSlots slots (buffer/fill_slots.frag): the i-th at i * uPixels + pixel.
// (Reading the unsorted records as a buffer texture instead was tried, issue #29: no faster on the
// 16-layer stack, 0.7 ms slower on the torus.)
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_PIXEL_CURSOR) readonly buffer ListHead { uint listHead[]; };
layout(std430, binding = BIND_LIST_NEXT) readonly buffer ListNext { uint listNext[]; };
layout(std430, binding = BIND_FRAGS_UNSORTED) readonly buffer Frags { uint frags[]; };
uint unsortedWord(uint i) { return frags[i]; }
layout(std430, binding = BIND_FRAGS_SORTED) writeonly buffer Sorted { uint sorted[]; };
// Per fragment: (depth bits, source index). Positive floats order like their bit patterns, so
// the keys compare as integers, and each pixel's keys sit together in memory.
layout(std430, binding = BIND_ORDER) buffer Order { uvec2 order[]; };
uniform uint uPixels;
// The longest list sorted in registers (REGISTER_SORT, or 0: every list in the order buffer).
uniform uint uRegisterSortMax;

// The copy into the sorted block: words 0 and 1 (depth, triangle) are known, the rest are read.
void storeRecord(uint dst, uint depthBits, uint prim, uint src) {
  sorted[fragWord(dst, OFF_DEPTH)] = depthBits;
  sorted[fragWord(dst, OFF_PRIM)] = prim;
  for (uint w = 2u; w < uint(TLAB_STRIDE); ++w) sorted[fragWord(dst, w)] = unsortedWord(fragWord(src, w));
}

// Longer lists, and every linked list: insertion sort of (depth, source) keys in the order
// buffer, ties by triangle, then by position (the sort is stable).
bool before(uvec2 a, uvec2 b) {
  if (a.x != b.x) return a.x < b.x;
  return unsortedWord(fragWord(a.y, OFF_PRIM)) < unsortedWord(fragWord(b.y, OFF_PRIM));
}

uvec2 keyOf(uint src) { return uvec2(unsortedWord(fragWord(src, OFF_DEPTH)), src); }

void sortInOrderBuffer(uint pixel, uint base, uint n) {
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
  // Insertion sort of the indices.
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
    storeRecord(base + i, order[base + i].x, unsortedWord(fragWord(src, OFF_PRIM)), src);
  }
}

#ifndef TLAB_LINKED_LIST
// Lists up to REGISTER_SORT long: insertion sort of the keys (depth bits, triangle, source) in
// registers. The source index grows with the position in the list (slot i * uPixels + pixel, or
// head + i), so ordering by (depth, triangle, source) is the stable order of the insertion sort
// above. Every index into r is a constant (r stays in registers), and the work sits in loops of n
// steps: llvmpipe runs both sides of every branch under a mask, but leaves a loop once no lane
// needs it, so a group of invocations pays for its longest list, not for REGISTER_SORT.
const uint REGISTER_SORT = 16u;
uvec3 r[REGISTER_SORT];
bool keyBefore(uvec3 a, uvec3 b) { return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z); }
// Inserts `key` into the sorted r[0..15] (past the list: the largest key): r[k] takes r[k - 1]
// where key goes before r[k - 1], key where it goes before r[k] only, else stays.
#define SHIFT(k) { bool beforePrev = keyBefore(key, r[k - 1]); r[k] = beforePrev ? r[k - 1] : (beforeHere ? key : r[k]); beforeHere = beforePrev; }
#define SHIFT4(k) SHIFT(k + 3) SHIFT(k + 2) SHIFT(k + 1) SHIFT(k)
#define POP(k) r[k] = r[k + 1];
#define POP4(k) POP(k) POP(k + 1) POP(k + 2) POP(k + 3)
#define PAD4(k) r[k] = r[k + 1] = r[k + 2] = r[k + 3] = uvec3(0xFFFFFFFFu);  // (no key: depth is never NaN)

uint sourceOf(uint pixel, uint base, uint i) {
#ifdef TLAB_SLOTS
  return i * uPixels + pixel;
#else
  return base + i;
#endif
}

void sortInRegisters(uint pixel, uint base, uint n) {
  PAD4(0u) PAD4(4u) PAD4(8u) PAD4(12u)
  for (uint i = 0u; i < n; ++i) {
    uint src = sourceOf(pixel, base, i);
    uvec3 key = uvec3(unsortedWord(fragWord(src, OFF_DEPTH)), unsortedWord(fragWord(src, OFF_PRIM)), src);
    bool beforeHere = keyBefore(key, r[15]);
    SHIFT4(12u) SHIFT4(8u) SHIFT4(4u) SHIFT(3u) SHIFT(2u) SHIFT(1u)
    if (beforeHere) r[0] = key;
  }
  for (uint i = 0u; i < n; ++i) {  // front to back: store the first, move the rest up
    storeRecord(base + i, r[0].x, r[0].y, r[0].z);
    POP4(0u) POP4(4u) POP4(8u) POP(12u) POP(13u) POP(14u)
  }
}
#endif

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uPixels) return;
  uint n = pixelCount[pixel];
  if (n == 0u) return;
  uint base = pixelHead[pixel];
#ifndef TLAB_LINKED_LIST
  bool inRegisters = n <= min(uRegisterSortMax, REGISTER_SORT);
  sortInRegisters(pixel, base, inRegisters ? n : 0u);
  if (inRegisters) return;
#endif
  sortInOrderBuffer(pixel, base, n);
}
