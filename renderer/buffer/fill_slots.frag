#version 450 core
// Fill in one rasterization (issue #29): every fragment increments its pixel's counter, as the
// count pass does, and the first uSlots fragments of each pixel store their records straight
// into slots: the i-th fragment of a pixel is record i * uPixels + pixel, so slot i of
// neighbouring pixels are neighbouring records (the sort's invocations, one per pixel, then read
// adjacent memory, and slots no pixel reaches are never touched). A pixel with more fragments than
// slots only records how many it had (overflowMax); the host then falls back to the scatter
// pass, whose prefix sum these exact counts already give. Either way the sort pass receives
// every fragment, so the sorted buffer is the same.
#include "frame/fragment_layout.glsl"
#include "frame/surface_shading.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_COUNTERS) buffer Counters { uint fragCount; uint total; uint overflowMax; };
uniform int uWidth;
uniform uint uSlots;
uniform uint uPixels;
#include "buffer/fragment_record.glsl"

void main() {
  captureDerivatives();
  uint pixel = uint(gl_FragCoord.y) * uint(uWidth) + uint(gl_FragCoord.x);
  uint i = atomicAdd(pixelCount[pixel], 1u);
  if (i < uSlots) writeFragmentRecord(i * uPixels + pixel);
  else atomicMax(overflowMax, i + 1u);
}
