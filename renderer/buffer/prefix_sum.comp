#version 450 core
// Exclusive prefix sum of the per-pixel fragment counts → pixelHead (Carnecky Sec. 4.3: each
// pixel's fragments occupy one contiguous block). Three phases (TLAB_PHASE 1, 2, 3): block sums,
// a scan of the block sums, then each block's running sum.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_LIST_NEXT) buffer BlockSums { uint blockSum[]; };
layout(std430, binding = BIND_COUNTERS) buffer Counters { uint fragCount; uint total; };
uniform uint uPixels;
uniform uint uBlocks;
const uint BLOCK = 256u;

void main() {
  uint block = linearInvocation();
#if TLAB_PHASE == 1
  if (block >= uBlocks) return;
  uint sum = 0u;
  uint end = min(uPixels, (block + 1u) * BLOCK);
  for (uint p = block * BLOCK; p < end; ++p) sum += pixelCount[p];
  blockSum[block] = sum;
#elif TLAB_PHASE == 2
  if (block != 0u) return;
  uint running = 0u;
  for (uint b = 0u; b < uBlocks; ++b) {
    uint s = blockSum[b];
    blockSum[b] = running;
    running += s;
  }
  total = running;
#else
  if (block >= uBlocks) return;
  uint running = blockSum[block];
  uint end = min(uPixels, (block + 1u) * BLOCK);
  for (uint p = block * BLOCK; p < end; ++p) {
    pixelHead[p] = running;
    running += pixelCount[p];
  }
#endif
}
