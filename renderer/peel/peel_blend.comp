#version 450 core
// Blend stage of the depth-peeling loop (IRIS Sec. 5.1): Sobel silhouettes on this layer's
// normal and depth images, then front-to-back ("under") blending into a float accumulator
// (c, T): c ← c + T·α·c_i, T ← T·(1 − α).
#include "frame/compute_index.glsl"
#include "frame/sobel_silhouette.glsl"
layout(std430, binding = 9) buffer Accumulator { vec4 accum[]; };
layout(binding = 0) uniform sampler2D uLayerColor;
layout(binding = 1) uniform sampler2D uLayerNormalDepth;
uniform int uWidth;
uniform int uHeight;

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uint(uWidth * uHeight)) return;
  ivec2 xy = ivec2(int(pixel % uint(uWidth)), int(pixel / uint(uWidth)));
  vec4 nd = texelFetch(uLayerNormalDepth, xy, 0);
  if (nd.w == 0.0) return;  // no fragment in this layer
  vec4 ca = texelFetch(uLayerColor, xy, 0);
  if (SILHOUETTES != 0) {
    float depth[9];
    vec3 normal[9];
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        int k = (dy + 1) * 3 + (dx + 1);
        ivec2 q = xy + ivec2(dx, dy);
        bool inside = q.x >= 0 && q.y >= 0 && q.x < uWidth && q.y < uHeight;
        vec4 s = inside ? texelFetch(uLayerNormalDepth, q, 0) : vec4(0.0);
        depth[k] = s.w;
        normal[k] = s.xyz;
      }
    ca = applySilhouette(ca, sobelStrength(depth, normal));
  }
  vec4 a = accum[pixel];
  a.rgb += a.w * ca.a * ca.rgb;
  a.w *= 1.0 - ca.a;
  accum[pixel] = a;
}
