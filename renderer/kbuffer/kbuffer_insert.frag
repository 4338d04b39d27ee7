#version 450 core
// Z pass of the bucketed k-buffer (seed 002, Sec. 4.1 "Z insertion", Sec. 4.2): the k nearest
// fragments per pixel in depth order. Each atomicMin keeps the smaller key in its slot and the
// larger one moves on to the next slot; a key pushed past slot k is dropped.
#include "kbuffer/kbuffer_layout.glsl"
layout(std430, binding = BIND_KB_Z) coherent buffer Z { uint z[]; };
#include "kbuffer/kbuffer_fragment.glsl"

void main() {
  uint key = packDepthFirst(currentDepth16(), currentShape());
  uint base = slotOf(currentPixel(), 0u);
  for (uint i = 0u; i < uint(TLAB_K); ++i) {
    uint old = atomicMin(z[base + i], key);
    key = max(old, key);
    if (key == KB_EMPTY) break;
  }
}
