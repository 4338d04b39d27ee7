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

uniform int uLighting;  // 0: none, 1: headlight, 2: physically based

vec3 shadeSurface(uint object, bool frontFacing, vec3 viewNormal, vec3 viewPosition) {
  vec3 base = frontFacing ? objects[object].frontColor.rgb : objects[object].backColor.rgb;
  if (uLighting == 0) return base;
  vec3 n = normalize(viewNormal);
  vec3 toEye = normalize(-viewPosition);
  if (uLighting == 2) return shadePhysical(base, dot(n, toEye) < 0.0 ? -n : n, toEye);
  float diffuse = abs(dot(n, toEye));
  return base * (0.25 + 0.75 * diffuse);
}
