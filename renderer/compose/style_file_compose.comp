#version 450 core
// A style file's compositing stage: one invocation per pixel; the user's
//   vec4 composite()
// reads the pixel's fragments front to back (fragmentCount(), fragment(i)) and returns its colour.
#include "ops/style_file_prelude.glsl"
layout(std430, binding = BIND_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
// TLAB_STYLE_CODE

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uPixels) return;
  gPixel = pixel;
  gCount = pixelCount[pixel];
  gBase = pixelHead[pixel];
  outColor[pixel] = vec4(composite().rgb, 1.0);
}
