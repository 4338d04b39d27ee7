#version 450 core
// Sort pass (Carnecky Sec. 4.3): each pixel's fragments, front to back, into the contiguous
// block [pixelHead, pixelHead + pixelCount) of the sorted buffer (fragData2). Ties in depth are
// broken by the global triangle index, then by the order the fragments arrived in, so the order
// never depends on thread scheduling. One invocation per pixel that holds a fragment
// (frame/covered_pixels.glsl).
// TLAB_LINKED_LIST: the unsorted fragments are a linked list (Alg. 1) instead of a block.
// TLAB_SLOTS: they sit in uSlots slots (buffer/fill_slots.frag): the i-th at i * uPixels + pixel.
// (Reading the unsorted records as a buffer texture instead was tried, issue #29: no faster on the
// 16-layer stack, 0.7 ms slower on the torus.)
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
#include "frame/covered_pixels.glsl"
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
#ifdef TLAB_HAS_DEPTH_GRADIENT
// Each list's (max |∂z/∂x|, max |∂z/∂y|), the connect pass's maxStep (ops/connect.comp): the sort
// reads every record anyway, so the connect pass needs no pass of its own over the gradients.
layout(std430, binding = BIND_LIST_STEPS) writeonly buffer ListSteps { vec2 listSteps[]; };
vec2 gListStep = vec2(0.0);
#endif
#ifdef TLAB_COLOR_PLANE
// Each fragment's colour word again, one word a fragment in the sorted order (FillSpec::colorPlane):
// a compositor that reads nothing of the records but the colour (compose/smart_compose.comp) then
// reads 4 contiguous bytes a fragment, not one word of each record (issue #29).
layout(std430, binding = BIND_COLOR_PLANE) writeonly buffer ColorPlane { uint colorPlane[]; };
#endif
uniform uint uPixels;
// The longest list sorted in registers (REGISTER_SORT, or 0: every list in the order buffer).
uniform uint uRegisterSortMax;

// The copy into the sorted block: words 0 and 1 (depth, triangle) are known, the rest are read;
// records padded to quads of words (TLAB_RECORD_QUADS) are copied a uvec4 at a time.
#ifdef TLAB_RECORD_QUADS
layout(std430, binding = BIND_FRAGS_UNSORTED) readonly buffer FragQuads { uvec4 fragQuads[]; };
layout(std430, binding = BIND_FRAGS_SORTED) writeonly buffer SortedQuads { uvec4 sortedQuads[]; };
void storeRecord(uint dst, uint depthBits, uint prim, uint src) {
  uvec4 quads[TLAB_RECORD_QUADS];
  for (uint q = 0u; q < TLAB_RECORD_QUADS; ++q) {
    quads[q] = fragQuads[src * TLAB_RECORD_QUADS + q];
    sortedQuads[dst * TLAB_RECORD_QUADS + q] = quads[q];
  }
#ifdef TLAB_COLOR_PLANE
  colorPlane[dst] = quadWord(quads, TLAB_OFF_COLOR);
#endif
#ifdef TLAB_HAS_DEPTH_GRADIENT
  const uint g = TLAB_OFF_DEPTH_GRADIENT;
  vec2 gradient = uintBitsToFloat(uvec2(quadWord(quads, g), quadWord(quads, g + 1u)));
  gListStep = max(gListStep, abs(gradient));
#endif
}
#else
void storeRecord(uint dst, uint depthBits, uint prim, uint src) {
  sorted[fragWord(dst, OFF_DEPTH)] = depthBits;
  sorted[fragWord(dst, OFF_PRIM)] = prim;
  for (uint w = 2u; w < uint(TLAB_STRIDE); ++w) sorted[fragWord(dst, w)] = unsortedWord(fragWord(src, w));
#ifdef TLAB_COLOR_PLANE
  colorPlane[dst] = unsortedWord(fragWord(src, TLAB_OFF_COLOR));
#endif
#ifdef TLAB_HAS_DEPTH_GRADIENT
  uint g = fragWord(src, TLAB_OFF_DEPTH_GRADIENT);
  gListStep = max(gListStep, abs(vec2(uintBitsToFloat(unsortedWord(g)), uintBitsToFloat(unsortedWord(g + 1u)))));
#endif
}
#endif

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
// Lists up to REGISTER_SORT long, sorted in registers (buffer/key_network.glsl). The key of a
// list's i-th fragment is (depth bits, triangle * 16 + i) (the host sends uRegisterSortMax = 0 when
// a triangle index needs more than 28 bits). The source index grows with i (slot i * uPixels +
// pixel, or head + i), so this order is (depth, triangle, source), the stable order of the
// insertion sort above. The keys are shifted into the registers (the rest padded with the largest
// key), sorted by the network of 16 (63 compare-exchanges, where inserting 16 keys into 16
// registers took 256 compare-selects), and stored front to back. llvmpipe runs both sides of every
// branch under a lane mask, and a loop's body once, then again while a lane of the group of 8
// needs it: the network costs every group once (hence no invocation for an empty pixel), the
// loads and stores the group's longest list. (Two runs of 8 filled by insertion and merged, 25
// compare-exchanges, were a little faster on the torus's short lists and slower on the 16-layer
// stack, issue #29.)
// TLAB_REGISTER_SORT 8: every list of the frame fits 8 (the host knows it from the slots): 8
// registers and the network of 8 (19 compare-exchanges), for scenes of short lists such as the torus.
#if TLAB_REGISTER_SORT == 8
#define NET_SIZE 8
#else
#define NET_SIZE 16
#endif
#include "buffer/key_network.glsl"
const uint REGISTER_SORT = uint(NET_SIZE);

uint sourceOf(uint pixel, uint base, uint i) {
#ifdef TLAB_SLOTS
  return i * uPixels + pixel;
#else
  return base + i;
#endif
}

// A record's words 0 and 1 (depth, triangle): one uvec2 where records are padded to quads.
#ifdef TLAB_RECORD_QUADS
layout(std430, binding = BIND_FRAGS_UNSORTED) readonly buffer FragPairs { uvec2 fragPairs[]; };
uvec2 depthAndTriangle(uint src) { return fragPairs[src * TLAB_RECORD_QUADS * 2u]; }
#else
uvec2 depthAndTriangle(uint src) { return uvec2(unsortedWord(fragWord(src, OFF_DEPTH)), unsortedWord(fragWord(src, OFF_PRIM))); }
#endif

ivec2 keyAt(uint pixel, uint base, uint i) {
  uvec2 words = depthAndTriangle(sourceOf(pixel, base, i));
  return netKey(words.x, words.y, i);
}

void sortInRegisters(uint pixel, uint base, uint n) {
  netClear();
  for (uint i = 0u; i < n; ++i) { NET_PUSH(keyAt(pixel, base, i)) }
  NET_SORT
  for (uint i = 0u; i < n; ++i) {  // front to back: store the first, move the rest down
    uvec2 key = netWords(netKeys[0]);
    storeRecord(base + i, key.x, key.y >> 4u, sourceOf(pixel, base, netPosition(netKeys[0])));
    NET_NEXT
  }
}
#endif

void storeListStep(uint pixel) {
#ifdef TLAB_HAS_DEPTH_GRADIENT
  listSteps[pixel] = gListStep;
#endif
}

void main() {
  uint pixel;
  if (!coveredInvocation(pixel)) return;  // (an empty list has nothing to sort)
  uint n = pixelCount[pixel];
  uint base = pixelHead[pixel];
#ifndef TLAB_LINKED_LIST
  bool inRegisters = n <= min(uRegisterSortMax, REGISTER_SORT);
  sortInRegisters(pixel, base, inRegisters ? n : 0u);
  if (inRegisters) {
    storeListStep(pixel);
    return;
  }
#endif
  sortInOrderBuffer(pixel, base, n);
  storeListStep(pixel);
}
