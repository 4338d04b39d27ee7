#version 450 core
// Sets a field to uValue at every fragment of a frontier list: with the field cleared to 0 first,
// the initial β or γ of Sec. 5.3 from the seeds the connect pass listed (a seed starts at 1, every
// other fragment at 0), which its phase 2 then need not store for every fragment (issue #29).
// Dispatched indirectly from the list's header, as ops/spread_frontier.comp.
#include "ops/field_bindings.glsl"
layout(local_size_x = 64) in;  // FRONTIER_GROUP
layout(std430, binding = BIND_BETA_OUT) writeonly buffer Field { float u[]; };
FRONTIER_LIST(readonly, BIND_FRONTIER_IN, List, list);
uniform float uValue;

void main() {
  for (uint i = gl_GlobalInvocationID.x; i < list.count; i += gl_NumWorkGroups.x * FRONTIER_GROUP) u[list.items[i]] = uValue;
}
