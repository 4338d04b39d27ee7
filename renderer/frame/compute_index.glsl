// The linear index of this compute invocation when the host dispatched a 2-D grid of 64-wide
// groups (gpu::dispatchLinear): a 1-D grid would exceed the 65535-group limit at 2048x2048.
layout(local_size_x = 64) in;

uint linearInvocation() {
  return gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * 64u) + gl_GlobalInvocationID.x;
}
