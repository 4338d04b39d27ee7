#version 450 core
// Reorder and bucket creation of the bucketed k-buffer (seed 002, Sec. 4.1, Fig. 3 (2)-(3)),
// one invocation per pixel: Z's keys are swapped to shape id | depth and insertion-sorted, then
// each run of one shape becomes a bucket (b, i, j) stored in the pixel's hash table B at
// H(b) = b mod k, probing linearly past occupied slots.
#include "kbuffer/kbuffer_layout.glsl"
#include "frame/compute_index.glsl"
layout(std430, binding = BIND_KB_Z) buffer Z { uint z[]; };
layout(std430, binding = BIND_KB_TABLE) writeonly buffer Table { uint table[]; };
uniform uint uPixels;

void main() {
  uint pixel = linearInvocation();
  if (pixel >= uPixels) return;
  uint base = slotOf(pixel, 0u);
  uint keys[TLAB_K];
  uint n = 0u;
  for (uint i = 0u; i < uint(TLAB_K); ++i) {
    uint key = z[base + i];
    table[base + i] = KB_EMPTY;
    if (key == KB_EMPTY) continue;
    key = swapHalves(key);
    // Insertion sort (Sec. 6: nearly sorted lists make it close to O(k)).
    uint j = n;
    while (j > 0u && keys[j - 1u] > key) {
      keys[j] = keys[j - 1u];
      --j;
    }
    keys[j] = key;
    ++n;
  }
  for (uint i = 0u; i < n; ++i) z[base + i] = keys[i];
  uint slotsUsed[TLAB_K];
  for (uint i = 0u; i < uint(TLAB_K); ++i) slotsUsed[i] = 0u;
  for (uint i = 0u; i < n;) {
    uint b = shapeOfShapeFirst(keys[i]);
    uint j = i;
    while (j + 1u < n && shapeOfShapeFirst(keys[j + 1u]) == b) ++j;
    uint slot = b % uint(TLAB_K);                        // H(b) = b mod k
    while (slotsUsed[slot] != 0u) slot = (slot + 1u) % uint(TLAB_K);
    slotsUsed[slot] = 1u;
    table[base + slot] = (b << 16) | (i << 8) | j;
    i = j + 1u;
  }
}
