// Passes with nothing to do for a pixel without fragments run one invocation per pixel that holds
// one (FragmentBuffer::coveredPixels, in pixel order, dispatched over uCovered items): on a CPU
// rasterizer an invocation with nothing to do costs nearly as much as one with a short list, and
// a third of a typical picture is background. After frame/fragment_layout.glsl and
// frame/compute_index.glsl.
layout(std430, binding = BIND_COVERED) readonly buffer CoveredPixels { uint coveredPixel[]; };
uniform uint uCovered;

// This invocation's pixel; false beyond the list.
bool coveredInvocation(out uint pixel) {
  uint i = linearInvocation();
  pixel = i < uCovered ? coveredPixel[i] : 0u;
  return i < uCovered;
}
