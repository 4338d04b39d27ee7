#version 450 core
// Draws a silhouette-line fragment into the composed image where the rules of Diepstraten Sec. 4
// do not hide it: it must not lie behind the hiding depth the compositor found around that pixel
// (the first opaque surface, the second transparent front face, or with implicit boundaries the
// first transparent back face; nothing where the list ran out). A silhouette lies on the border
// of its surface, so the 3x3 neighbourhood decides: the pixel centre itself may just miss the
// surface, and the surface next to a silhouette is much nearer than the silhouette itself.
layout(std430, binding = 9) writeonly buffer Output { vec4 outColor[]; };
layout(std430, binding = 13) readonly buffer VisibleDepth { vec2 visibleDepth[]; };
uniform int uLimit;  // 0: the hiding depth (opaque objects' lines), 1: F1's (transparent objects')
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
      deepest = max(deepest, visibleDepth[q.y * uWidth + q.x][uLimit]);
    }
  if (vEyeDepth > deepest * (1.0 + uDepthTolerance)) discard;
  uint pixel = uint(xy.y * uWidth + xy.x);
  outColor[pixel] = vec4(uLineColor, 1.0);
}
