#version 450 core
// Draws a silhouette-line fragment into the composed image where it is not behind the deepest
// surface the compositor showed around that pixel (so lines of hidden objects stay hidden). A
// silhouette lies on the border of its surface, so the 3x3 neighbourhood decides: the pixel
// centre itself may just miss the surface.
layout(std430, binding = 9) writeonly buffer Output { vec4 outColor[]; };
layout(std430, binding = 13) readonly buffer VisibleDepth { float visibleDepth[]; };
in float vEyeDepth;
uniform int uWidth;
uniform int uHeight;
uniform vec3 uLineColor;
uniform float uDepthTolerance;  // relative

void main() {
  ivec2 xy = ivec2(gl_FragCoord.xy);
  float deepest = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = clamp(xy + ivec2(dx, dy), ivec2(0), ivec2(uWidth - 1, uHeight - 1));
      deepest = max(deepest, visibleDepth[q.y * uWidth + q.x]);
    }
  if (vEyeDepth > deepest * (1.0 + uDepthTolerance)) discard;
  uint pixel = uint(xy.y * uWidth + xy.x);
  outColor[pixel] = vec4(uLineColor, 1.0);
}
