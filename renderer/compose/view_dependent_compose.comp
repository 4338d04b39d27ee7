#version 450 core
// View-dependent transparency for technical illustration (Diepstraten et al. 2002, Secs. 4-6) on
// the illustration buffer. Walking each pixel's sorted list front to back, the rules of Sec. 4:
//  - faces of transparent objects never shine through: only the nearest transparent front face
//    F1 is blended; back faces of transparent objects are never drawn;
//  - opaque objects behind two transparent layers are hidden: the walk ends at a second
//    transparent front face (Sec. 6.2, explicit interior boundaries) or, with implicit interior
//    boundaries (Sec. 6.1), already at the first transparent back face;
//  - transparency falls off towards the edges: F1's α is interpolated from the per-vertex α of
//    Eq. 2 (ops/view_dependent_alpha.comp).
// Blending as in Sec. 7: c = α_T·c_T + w·c_dst (GL_SRC_ALPHA, GL_DST_ALPHA), c_dst the first
// opaque surface behind F1 with the user's w = α_opaque, else the background with α_background;
// by default both weights are divided by α_T + w where that exceeds 1 (no wash-out).
// An opaque surface in front of every transparent one is drawn as it is.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
#include "frame/surface_shading.glsl"
#include "frame/illustrative_shading.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
layout(std430, binding = BIND_OUTPUT) writeonly buffer Output { vec4 outColor[]; };
layout(std430, binding = 10) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 11) readonly buffer Triangles { uint triangles[]; };
layout(std430, binding = 12) readonly buffer VertexAlpha { float vertexAlpha[]; };
// Per pixel: the hiding depth, and the depth limit for transparent objects' lines (F1's depth:
// a transparent object's lines behind its own front face are not drawn, as in Fig. 5).
layout(std430, binding = 13) writeonly buffer VisibleDepth { vec2 visibleDepth[]; };
uniform int uWidth;
uniform int uHeight;
uniform vec4 uBackground;
uniform vec2 uProjectionScale;  // (P[0][0], P[1][1])
uniform mat4 uView;
uniform int uExplicitBoundaries;
uniform float uAlphaOpaque;
uniform float uAlphaBackground;
uniform int uAdditiveBlend;

const uint kRoleOpaque = 2u;  // Role::Opaque

float depthOf(uint f) { return uintBitsToFloat(sorted[fragWord(f, OFF_DEPTH)]); }

vec3 rayThrough(vec2 xy) {
  vec2 ndc = xy / vec2(uWidth, uHeight) * 2.0 - 1.0;
  return vec3(ndc / uProjectionScale, -1.0);
}

// α of Eq. 2 at the fragment: the per-vertex values interpolated with the barycentric
// coordinates where the pixel's ray meets the fragment's triangle (Möller-Trumbore, view space).
float interpolatedAlpha(uint f, vec3 ray) {
  uint t = sorted[fragWord(f, OFF_PRIM)];
  uint i0 = triangles[3u * t], i1 = triangles[3u * t + 1u], i2 = triangles[3u * t + 2u];
  vec3 p0 = (uView * positions[i0]).xyz, p1 = (uView * positions[i1]).xyz, p2 = (uView * positions[i2]).xyz;
  vec3 e1 = p1 - p0, e2 = p2 - p0;
  vec3 h = cross(ray, e2);
  float det = dot(e1, h);
  if (abs(det) < 1e-20) return (vertexAlpha[i0] + vertexAlpha[i1] + vertexAlpha[i2]) / 3.0;
  vec3 s = -p0;  // the eye is the origin
  float u = dot(s, h) / det;
  float v = dot(ray, cross(s, e1)) / det;
  vec3 b = clamp(vec3(1.0 - u - v, u, v), 0.0, 1.0);
  b /= max(b.x + b.y + b.z, 1e-20);
  return b.x * vertexAlpha[i0] + b.y * vertexAlpha[i1] + b.z * vertexAlpha[i2];
}

vec3 shade(uint f, vec3 ray) {
  uint ids = sorted[fragWord(f, TLAB_OFF_IDS)];
  SurfaceSample s;
  s.viewPosition = ray * depthOf(f);
  s.normal = decodeNormal(sorted[fragWord(f, TLAB_OFF_NORMAL)]);
  s.frontFacing = (ids & 0x80000000u) != 0u;
  s.object = ids & 0xFFFFu;
  s.layer = 0u;
  s.pixel = vec2(0.0);
  s.st = vec2(0.0);
  s.nzGradient = vec2(0.0);
  s.stGradient = vec4(0.0);
  Shaded c = shadeIllustrative(s);
  return c.diffuse + c.specular;
}

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uint(uWidth * uHeight)) return;
  uint n = pixelCount[pixel];
  uint base = pixelHead[pixel];
  vec3 ray = rayThrough(vec2(pixel % uint(uWidth), pixel / uint(uWidth)) + 0.5);
  int front = -1;   // F1: the nearest transparent front face
  int opaque = -1;  // the opaque surface that is drawn
  float hiding = 1e30;  // everything behind this depth is hidden (the rules); lines too
  for (uint i = 0u; i < n; ++i) {
    uint f = base + i;
    uint ids = sorted[fragWord(f, TLAB_OFF_IDS)];
    bool isOpaque = (objects[ids & 0xFFFFu].info.x & kRoleOpaque) != 0u;
    bool frontFacing = (ids & 0x80000000u) != 0u;
    if (isOpaque) {
      opaque = int(f);
      hiding = depthOf(f);
      break;
    }
    if (frontFacing) {
      if (front >= 0) {       // a second transparent front face hides everything behind it
        hiding = depthOf(f);
        break;
      }
      front = int(f);
    } else if (uExplicitBoundaries == 0 && front >= 0) {
      hiding = depthOf(f);    // Sec. 6.1: nothing behind the nearest transparent back face
      break;
    }
  }
  vec3 c = uBackground.rgb;
  if (front >= 0) {
    float alphaT = interpolatedAlpha(uint(front), ray);
    float w = opaque >= 0 ? uAlphaOpaque : uAlphaBackground;
    float norm = uAdditiveBlend == 0 ? max(1.0, alphaT + w) : 1.0;
    vec3 dst = w * (opaque >= 0 ? shade(uint(opaque), ray) : uBackground.rgb);
    c = clamp((alphaT * shade(uint(front), ray) + dst) / norm, 0.0, 1.0);
  } else if (opaque >= 0) {
    c = shade(uint(opaque), ray);
  }
  outColor[pixel] = vec4(c, 1.0);
  visibleDepth[pixel] = vec2(hiding, front >= 0 ? depthOf(uint(front)) : hiding);
}
