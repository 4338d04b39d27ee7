// What a style file's GLSL sees (params/style_program.hpp assembles prelude, parameters, the
// user's file, and a stage's main()). Fragments are read from the sorted illustration buffer;
// the Fragment struct holds exactly the properties the style declared (TLAB_HAS_*), so using an
// undeclared one is a compile error on the user's line.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
#define BIND_STYLE_VALUE_IN 20
#define BIND_STYLE_VALUE_OUT 21
#ifdef TLAB_STYLE_VALUES
layout(std430, binding = BIND_STYLE_VALUE_IN) readonly buffer ValueIn { float valueIn[]; };
#endif
uniform uint uPixels;
uniform uint uWidth;
uniform uint uHeight;
uniform vec4 uBackground;
uniform float uNear;
uniform float uFar;

struct Fragment {
  float depth;  // eye-space distance along the view axis
#ifdef TLAB_HAS_COLOR
  vec4 color;  // shaded colour (the style's `lighting`), alpha 1
#endif
#ifdef TLAB_HAS_NORMAL
  vec3 normal;  // view-space unit normal
#endif
#ifdef TLAB_HAS_DEPTH_GRADIENT
  vec2 depthGradient;  // (d depth/dx, d depth/dy) per pixel
#endif
#ifdef TLAB_HAS_IDS
  uint object;
  uint component;
  bool frontFacing;
#endif
#ifdef TLAB_HAS_ST
  vec2 st;  // surface parameters (s, t)
#endif
#ifdef TLAB_HAS_NZ_GRADIENT
  vec2 nzGradient;  // (d n_z/dx, d n_z/dy)
#endif
#ifdef TLAB_HAS_ST_GRADIENT
  vec4 stGradient;  // (ds/dx, ds/dy, dt/dx, dt/dy)
#endif
#ifdef TLAB_STYLE_VALUES
  float value;  // the per-fragment stage's result (neighbors = true)
#endif
};

Fragment readFragment(uint f) {
  Fragment r;
  r.depth = uintBitsToFloat(sorted[fragWord(f, OFF_DEPTH)]);
#ifdef TLAB_HAS_COLOR
  r.color = unpackUnorm4x8(sorted[fragWord(f, TLAB_OFF_COLOR)]);
#endif
#ifdef TLAB_HAS_NORMAL
  r.normal = decodeNormal(sorted[fragWord(f, TLAB_OFF_NORMAL)]);
#endif
#ifdef TLAB_HAS_DEPTH_GRADIENT
  r.depthGradient = vec2(uintBitsToFloat(sorted[fragWord(f, TLAB_OFF_DEPTH_GRADIENT)]),
                         uintBitsToFloat(sorted[fragWord(f, TLAB_OFF_DEPTH_GRADIENT) + 1u]));
#endif
#ifdef TLAB_HAS_IDS
  uint ids = sorted[fragWord(f, TLAB_OFF_IDS)];
  r.object = ids & 0xFFFFu;
  r.component = (ids >> 16) & 0x7FFFu;
  r.frontFacing = (ids >> 31) != 0u;
#endif
#ifdef TLAB_HAS_ST
  r.st = vec2(uintBitsToFloat(sorted[fragWord(f, TLAB_OFF_ST)]), uintBitsToFloat(sorted[fragWord(f, TLAB_OFF_ST) + 1u]));
#endif
#ifdef TLAB_HAS_NZ_GRADIENT
  r.nzGradient = vec2(uintBitsToFloat(sorted[fragWord(f, TLAB_OFF_NZ_GRADIENT)]),
                      uintBitsToFloat(sorted[fragWord(f, TLAB_OFF_NZ_GRADIENT) + 1u]));
#endif
#ifdef TLAB_HAS_ST_GRADIENT
  for (uint k = 0u; k < 4u; ++k) r.stGradient[k] = uintBitsToFloat(sorted[fragWord(f, TLAB_OFF_ST_GRADIENT) + k]);
#endif
#ifdef TLAB_STYLE_VALUES
  r.value = valueIn[f];
#endif
  return r;
}

// The pixel this invocation composites (the compositing stage; the per-fragment stage has none).
uint gPixel = 0u;
uint gCount = 0u;
uint gBase = 0u;

int fragmentCount() { return int(gCount); }               // fragments at this pixel
Fragment fragment(int i) { return readFragment(gBase + uint(i)); }  // i = 0 is the nearest
ivec2 pixelCoord() { return ivec2(gPixel % uWidth, uHeight - 1u - gPixel / uWidth); }  // row 0 = top
ivec2 frameSize() { return ivec2(uWidth, uHeight); }  // the image W×H
vec4 background() { return uBackground; }
float nearPlane() { return uNear; }
float farPlane() { return uFar; }

// The linked neighbours of a fragment in the per-fragment stage (Carnecky Alg. 2): the current
// values of the `count` existing ones, packed first.
struct Neighbors {
  int count;
  float value[4];
};
