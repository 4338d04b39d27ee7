#version 450 core
// Eq. 10 or 11 (compose/profile_modifier.glsl) applied in place to a list of a field's values, for
// smart transparency's blend as host code where the GL runs on the CPU (compose/host_blend.hpp,
// issue #29): the modifier stays the shader's own function (llvmpipe's exp and pow are its own
// approximations), so the host blends the very values compose/smart_compose.comp would.
#include "frame/compute_index.glsl"
#include "compose/profile_modifier.glsl"
layout(std430, binding = 0) buffer Values { float values[]; };
uniform uint uCount;

void main() {
  uint i = linearInvocation();
  if (i >= uCount) return;
  values[i] = modifyProfile(values[i]);
}
