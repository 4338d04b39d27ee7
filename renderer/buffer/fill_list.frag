#version 450 core
// Fill as in Carnecky Alg. 1: a global fragment counter hands out pool cells, and each pixel's
// list is linked through an atomic exchange of its head. Fragments beyond the pool's capacity
// are counted but dropped; the host then grows the pool and re-renders (Sec. 4.2).
#include "frame/fragment_layout.glsl"
#include "frame/surface_shading.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_CURSOR) buffer ListHead { uint listHead[]; };
layout(std430, binding = BIND_LIST_NEXT) writeonly buffer ListNext { uint listNext[]; };
layout(std430, binding = BIND_COUNTERS) buffer Counters { uint fragCount; uint total; };
uniform int uWidth;
uniform uint uCapacity;
#include "buffer/fragment_record.glsl"

void main() {
  captureDerivatives();
  uint pixel = uint(gl_FragCoord.y) * uint(uWidth) + uint(gl_FragCoord.x);
  atomicAdd(pixelCount[pixel], 1u);
  uint frag = atomicAdd(fragCount, 1u);                // Alg. 1, line 1
  if (frag < uCapacity) {                              // line 2
    uint previous = atomicExchange(listHead[pixel], frag);  // line 3
    listNext[frag] = previous;                         // line 4
    writeFragmentRecord(frag);
  }
}
