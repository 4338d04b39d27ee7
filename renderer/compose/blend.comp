#version 450 core
// Front-to-back alpha blending of each pixel's sorted fragment list with float accumulation:
//   c ← c + T·α·c_i,  T ← T·(1 − α),  and finally c ← c + T·c_background.
// The per-fragment opacity comes from TLAB_ALPHA_SOURCE: 0 = the uniform uAlpha (style
// `constant`); later styles provide their own per-fragment α.
//
// TLAB_FUSED (issue #29): the sort pass did not run; each invocation sorts its own pixel's list
// and blends it, so no sorted buffer is written. Lists of up to 4 fragments are sorted in
// registers by a fixed sorting network (every index a constant: no per-lane memory); with
// TLAB_NETWORK_SORT, lists of 5 to 16 by buffer/sort.comp's register network of 16 (the 16-layer
// stack's compose 3,080 → 610 M instructions a frame); longer ones by insertion sort of their
// (depth, source) keys in the order buffer at the pixel's block, as buffer/sort.comp sorts. The keys (depth bits, then triangle index) are unique within a pixel,
// so both give sort.comp's order, and the blend's arithmetic is the same, term by term.
// Measured on llvmpipe (issue #29): 4 registers beat 8 (a network of 8 made the compose pass
// 18.5-166 ms against 16.4-110 ms on the teapot, bunny, torus, abstract scene and 16-layer stack,
// best of 3 alternating rounds at load 5), and inserting each record into the registers as it is
// read, in loops, was slower than either.
// One invocation per pixel of uRect (x0, y0, width, height; frame/frame_context.hpp's
// sceneFootprint): the pixels around it have no fragment, and the host paints them.
// TLAB_SLOTS: the records sit in slots (buffer/fill_slots.frag: the i-th at i * uPixels + pixel),
// and so do the keys in the order buffer (the fill then needs no prefix sum: issue #29), else in
// the scatter pass's block [pixelHead, pixelHead + pixelCount).
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
#ifdef TLAB_FUSED
layout(std430, binding = BIND_FRAGS_UNSORTED) readonly buffer Frags { uint frags[]; };
layout(std430, binding = BIND_ORDER) buffer Order { uvec2 order[]; };
#else
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
#endif
uniform uint uPixels;
uniform int uWidth;
uniform ivec4 uRect;
uniform vec4 uBackground;
uniform float uAlpha;

vec3 c = vec3(0.0);
float T = 1.0;  // remaining transmittance

void blendFragment(uint colorWord) {
  vec3 ci = unpackUnorm4x8(colorWord).rgb;
  float a = uAlpha;
  c += T * a * ci;
  T *= 1.0 - a;
}

#ifdef TLAB_FUSED
// Where the i-th record of a pixel, and the i-th key of its order, sit.
#ifdef TLAB_SLOTS
uint recordOf(uint pixel, uint base, uint i) { return i * uPixels + pixel; }
#else
uint recordOf(uint pixel, uint base, uint i) { return base + i; }
#endif
#define KEY(i) order[recordOf(pixel, base, i)]

// One record in registers: (depth bits, triangle index, colour word).
uvec3 loadRecord(uint record) {
  return uvec3(frags[fragWord(record, OFF_DEPTH)], frags[fragWord(record, OFF_PRIM)],
               frags[fragWord(record, TLAB_OFF_COLOR)]);
}
bool before(uvec3 a, uvec3 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; }

const uint REGISTER_SORT = 4u;
uvec3 r[REGISTER_SORT];
// Compare-exchange of two constant indices.
#define CE(i, j) { uvec3 lo = before(r[j], r[i]) ? r[j] : r[i]; uvec3 hi = before(r[j], r[i]) ? r[i] : r[j]; r[i] = lo; r[j] = hi; }

void blendInRegisters(uint pixel, uint base, uint n) {
  for (uint i = 0u; i < REGISTER_SORT; ++i)
    r[i] = i < n ? loadRecord(recordOf(pixel, base, i)) : uvec3(0xFFFFFFFFu);  // padding sorts last
  if (n > 2u) {  // the optimal network of 4 (5 compare-exchanges)
    CE(0, 1) CE(2, 3) CE(0, 2) CE(1, 3) CE(1, 2)
  } else if (n == 2u) {
    CE(0, 1)
  }
  for (uint i = 0u; i < REGISTER_SORT; ++i)
    if (i < n) blendFragment(r[i].z);
}

#ifdef TLAB_NETWORK_SORT
// Frames whose slots hold lists longer than 8 (the host knows the longest list from the slots):
// lists of 5 to 16 as keys (depth bits, triangle * 16 + i) sorted by the register network of 16,
// as buffer/sort.comp sorts, then their colours through the keys. A shader of its own: llvmpipe
// runs every branch's code under a lane mask, so in a frame of short lists (the torus: 2 at most)
// the network's code alone cost 35 M instructions a frame (issue #29, callgrind).
#define NET_SIZE 16
#include "buffer/key_network.glsl"
const uint NETWORK_SORT = 16u;

void blendInNetwork(uint pixel, uint base, uint n) {
  netClear();
  for (uint i = 0u; i < n; ++i) {
    uint src = recordOf(pixel, base, i);
    NET_PUSH(netKey(frags[fragWord(src, OFF_DEPTH)], frags[fragWord(src, OFF_PRIM)], i))
  }
  NET_SORT
  for (uint i = 0u; i < n; ++i) {
    blendFragment(frags[fragWord(recordOf(pixel, base, netPosition(netKeys[0])), TLAB_OFF_COLOR)]);
    NET_NEXT
  }
}
#else
const uint NETWORK_SORT = REGISTER_SORT;
#endif

// Longer lists: buffer/sort.comp's insertion sort of the keys, then the colours through them.
bool keyBefore(uvec2 a, uvec2 b) {
  if (a.x != b.x) return a.x < b.x;
  return frags[fragWord(a.y, OFF_PRIM)] < frags[fragWord(b.y, OFF_PRIM)];
}

void blendInOrderBuffer(uint pixel, uint base, uint n) {
  for (uint i = 0u; i < n; ++i) {
    uint src = recordOf(pixel, base, i);
    KEY(i) = uvec2(frags[fragWord(src, OFF_DEPTH)], src);
  }
  for (uint i = 1u; i < n; ++i) {
    uvec2 key = KEY(i);
    uint j = i;
    while (j > 0u && keyBefore(key, KEY(j - 1u))) {
      KEY(j) = KEY(j - 1u);
      --j;
    }
    KEY(j) = key;
  }
  for (uint i = 0u; i < n; ++i) blendFragment(frags[fragWord(KEY(i).y, TLAB_OFF_COLOR)]);
}
#endif

void main() {
  uint i = linearInvocation();
  if (i >= uint(uRect.z * uRect.w)) return;
  uint pixel = uint(uRect.y + int(i) / uRect.z) * uint(uWidth) + uint(uRect.x + int(i) % uRect.z);
  uint n = pixelCount[pixel];
#if defined(TLAB_FUSED) && defined(TLAB_SLOTS)
  uint base = 0u;  // slots need no block
#else
  uint base = pixelHead[pixel];
#endif
#ifdef TLAB_FUSED
  if (n > NETWORK_SORT) blendInOrderBuffer(pixel, base, n);
#ifdef TLAB_NETWORK_SORT
  else if (n > REGISTER_SORT) blendInNetwork(pixel, base, n);
#endif
  else if (n > 0u) blendInRegisters(pixel, base, n);
#else
  for (uint i = 0u; i < n; ++i) blendFragment(sorted[fragWord(base + i, TLAB_OFF_COLOR)]);
#endif
  outColor[pixel] = vec4(c + T * uBackground.rgb, 1.0);
}
