#version 450 core
// A style file's per-fragment stage (neighbors = true): one invocation per fragment of the sorted
// buffer. Iteration 0 writes the user's
//   float initialValue(Fragment f)
// and every later iteration
//   float iterate(Fragment f, Neighbors n)
// with f.value the fragment's current value and n the current values of its linked neighbours
// (Carnecky Alg. 2 links from ops/connect.comp: the mutual-best continuation of its surface in
// the four adjacent pixels' lists). The compositing stage then reads fragment(i).value.
#include "ops/style_file_prelude.glsl"
#include "ops/field_bindings.glsl"
layout(std430, binding = BIND_LINKS) readonly buffer Links { uvec4 links[]; };
layout(std430, binding = BIND_STYLE_VALUE_OUT) writeonly buffer ValueOut { float valueOut[]; };
uniform uint uFragments;
uniform int uIteration;
// TLAB_STYLE_CODE

void main() {
  uint f = linearInvocation();
  if (f >= uFragments) return;
  Fragment self = readFragment(f);
  if (uIteration == 0) {
    valueOut[f] = initialValue(self);
    return;
  }
  Neighbors n;
  n.count = 0;
  for (int k = 0; k < 4; ++k) n.value[k] = 0.0;
  uvec4 l = links[f];
  for (int k = 0; k < 4; ++k)
    if (l[k] != NO_NEIGHBOR) n.value[n.count++] = valueIn[l[k]];
  valueOut[f] = iterate(self, n);
}
