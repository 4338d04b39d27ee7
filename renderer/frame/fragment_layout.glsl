// The layout of one fragment record in the illustration buffer (Carnecky Sec. 4.1, fragData):
// TLAB_STRIDE 32-bit words per fragment; words 0-1 are always depth and the sort key; the rest
// exist only when the style asked for them (TLAB_HAS_* / TLAB_OFF_* come from FragmentLayout).
// Binding points shared by every illustration-buffer pass.
#define BIND_PIXEL_COUNT 0
#define BIND_PIXEL_HEAD 1
#define BIND_PIXEL_CURSOR 2
#define BIND_LIST_NEXT 3
#define BIND_COUNTERS 4
#define BIND_FRAGS_UNSORTED 5
#define BIND_FRAGS_SORTED 6
#define BIND_ORDER 7
#define BIND_OBJECTS 8
#define BIND_OUTPUT 9
#define BIND_LIST_STEPS 27  // each list's max |∂z/∂x|, max |∂z/∂y| (buffer/sort.comp, read by ops/connect.comp)
#define BIND_COVERED 28      // the pixels holding a fragment, in pixel order (buffer/prefix_sum.comp)
#define BIND_COLOR_PLANE 29  // each fragment's colour word alone, in sorted order (buffer/sort.comp, TLAB_COLOR_PLANE)

#ifndef TLAB_STRIDE
#define TLAB_STRIDE 2u  // passes that read no fragment records
#endif

#define OFF_DEPTH 0u
#define OFF_PRIM 1u

uint fragWord(uint frag, uint offset) { return frag * uint(TLAB_STRIDE) + offset; }
#ifdef TLAB_RECORD_QUADS
// Word `offset` of a record held as its quads of words (a constant offset picks one register).
uint quadWord(uvec4 q[TLAB_RECORD_QUADS], uint offset) { return q[offset >> 2u][offset & 3u]; }
#endif

// Unit normals in one word: octahedral mapping, two 16-bit signed-normalised components
// (angular error below 0.01 degrees), so a record stays within the 128 MiB block limit longer.
vec2 octahedralWrap(vec2 v) { return (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }
uint encodeNormal(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  return packSnorm2x16(n.z >= 0.0 ? n.xy : octahedralWrap(n.xy));
}
vec3 decodeNormal(uint word) {
  vec2 e = unpackSnorm2x16(word);
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = octahedralWrap(n.xy);
  return normalize(n);
}
