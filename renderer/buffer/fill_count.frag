#version 450 core
// Fill, first half (count pass): every fragment increments its pixel's counter. No global
// atomic: llvmpipe's threads only meet on the same pixel.
#include "frame/fragment_layout.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) buffer PixelCount { uint pixelCount[]; };
uniform int uWidth;

void main() {
  uint pixel = uint(gl_FragCoord.y) * uint(uWidth) + uint(gl_FragCoord.x);
  atomicAdd(pixelCount[pixel], 1u);
}
