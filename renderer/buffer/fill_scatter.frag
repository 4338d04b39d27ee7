#version 450 core
// Fill, second half (scatter pass): each fragment takes the next slot of its pixel's contiguous
// range [pixelHead, pixelHead + pixelCount) and stores its properties there.
#include "frame/fragment_layout.glsl"
#include "frame/surface_shading.glsl"
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_PIXEL_CURSOR) buffer PixelCursor { uint pixelCursor[]; };
uniform int uWidth;
uniform uint uCapacity;
#include "buffer/fragment_record.glsl"

void main() {
  captureDerivatives();
  uint pixel = uint(gl_FragCoord.y) * uint(uWidth) + uint(gl_FragCoord.x);
  uint frag = pixelHead[pixel] + atomicAdd(pixelCursor[pixel], 1u);
  if (frag < uCapacity) writeFragmentRecord(frag);
}
