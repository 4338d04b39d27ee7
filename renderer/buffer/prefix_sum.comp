#version 450 core
// Exclusive prefix sum of the per-pixel fragment counts → pixelHead (Carnecky Sec. 4.3: each
// pixel's fragments occupy one contiguous block), and beside it the list of the pixels that hold a
// fragment, in pixel order: the same scan over (count, count > 0). Three phases (TLAB_PHASE 1, 2,
// 3): block sums, a scan of the block sums, then each block's running sums.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_LIST_NEXT) buffer BlockSums { uvec2 blockSum[]; };  // (fragments, covered pixels)
layout(std430, binding = BIND_COUNTERS) buffer Counters { uint fragCount; uint total; uint overflowMax; uint covered; };
layout(std430, binding = BIND_COVERED) writeonly buffer Covered { uint coveredPixel[]; };
uniform uint uPixels;
uniform uint uBlocks;
const uint BLOCK = 256u;

void main() {
  uint block = linearInvocation();
#if TLAB_PHASE == 1
  if (block >= uBlocks) return;
  uvec2 sum = uvec2(0u);
  uint end = min(uPixels, (block + 1u) * BLOCK);
  for (uint p = block * BLOCK; p < end; ++p) {
    uint n = pixelCount[p];
    sum += uvec2(n, min(n, 1u));
  }
  blockSum[block] = sum;
#elif TLAB_PHASE == 2
  if (block != 0u) return;
  uvec2 running = uvec2(0u);
  for (uint b = 0u; b < uBlocks; ++b) {
    uvec2 s = blockSum[b];
    blockSum[b] = running;
    running += s;
  }
  total = running.x;
  covered = running.y;
#else
  if (block >= uBlocks) return;
  uvec2 running = blockSum[block];
  uint end = min(uPixels, (block + 1u) * BLOCK);
  for (uint p = block * BLOCK; p < end; ++p) {
    uint n = pixelCount[p];
    pixelHead[p] = running.x;
    if (n > 0u) coveredPixel[running.y] = p;
    running += uvec2(n, min(n, 1u));
  }
#endif
}
