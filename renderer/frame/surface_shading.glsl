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

// Each lighting model sits in a loop of 0 or 1 turns rather than behind an `if`: llvmpipe
// evaluates both sides of an `if` for every fragment, under a mask, even when the condition is a
// uniform, so every fill paid for the physically based model whatever the lighting; it leaves a
// loop at once when no fragment needs it (issue #29).
vec3 shadeSurface(uint object, bool frontFacing, vec3 viewNormal, vec3 viewPosition) {
  vec3 base = frontFacing ? objects[object].frontColor.rgb : objects[object].backColor.rgb;
  vec3 shaded = base;  // lighting=none
  for (int once = 0; once < (uLighting == 1 ? 1 : 0); ++once) {  // the headlight
    vec3 n = normalize(viewNormal);
    vec3 toEye = normalize(-viewPosition);
    float diffuse = abs(dot(n, toEye));
    shaded = base * (0.25 + 0.75 * diffuse);
  }
  for (int once = 0; once < (uLighting == 2 ? 1 : 0); ++once) {  // physically based
    vec3 n = normalize(viewNormal);
    vec3 toEye = normalize(-viewPosition);
    shaded = shadePhysical(base, dot(n, toEye) < 0.0 ? -n : n, toEye);
  }
  return shaded;
}
