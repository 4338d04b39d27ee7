// Shading of a fragment before any transparency: the object's front or back colour, lit by a
// headlight (two-sided diffuse plus ambient), physically based (frame/physical_shading.glsl,
// lighting=pbr) or unlit (lighting=none).
#include "frame/physical_shading.glsl"
struct ObjectRecord {
  vec4 frontColor;
  vec4 backColor;
  uvec4 info;  // x: role flags, y: group, z: component id offset, w: unused
};
layout(std430, binding = BIND_OBJECTS) readonly buffer ObjectTable { ObjectRecord objects[]; };

// shadeSurface exists where the program compiled a lighting model in, TLAB_LIGHTING = 0: none,
// 1: headlight, 2: physically based (withLighting, frame/raster_uniforms.hpp). It was a uniform,
// and llvmpipe runs both sides of an `if` under a lane mask: every fragment also paid for the
// shading it did not use, the physically based one (issue #29: a sixth of the torus's fill).
#ifdef TLAB_LIGHTING
#define LIGHTING_MODEL TLAB_LIGHTING
vec3 shadeSurface(uint object, bool frontFacing, vec3 viewNormal, vec3 viewPosition) {
  vec3 base = frontFacing ? objects[object].frontColor.rgb : objects[object].backColor.rgb;
  if (LIGHTING_MODEL == 0) return base;
  vec3 n = normalize(viewNormal);
  vec3 toEye = normalize(-viewPosition);
  if (LIGHTING_MODEL == 2) return shadePhysical(base, dot(n, toEye) < 0.0 ? -n : n, toEye);
  float diffuse = abs(dot(n, toEye));
  return base * (0.25 + 0.75 * diffuse);
}
#endif
