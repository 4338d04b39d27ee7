// The surfaces dynamic transparency draws at one pixel (Elmqvist et al., seed 004, Secs. V.1-V.3),
// from the pixel's sorted fragment list instead of a frame buffer:
//  1. objects are solids: only the front-most fragment of each object is a surface (Sec. IV.1;
//     Sec. V.3 step 1 renders each object to the Z-buffer first) — so targets self-occlude;
//  2. surfaces are drawn in the objects' back-to-front group order (Alg. 1, drawRank from
//     ops/group_draw_order), impenetrable objects first (Sec. V.2);
//  3. a Z-test as in the frame buffer: a surface is drawn only when it is nearer than every
//     surface drawn before it;
//  4. layer control (Sec. III.6): with uMaxLayers = L > 0 only the nearest L + 1 drawn surfaces
//     are kept, and the deepest of them is opaque: at most L layers are uncovered.
// The kept surfaces end up in gSurface[0 .. gSurfaceCount), back to front.
// Needs frame/fragment_layout.glsl, frame/surface_shading.glsl and the sorted-list bindings.
layout(std430, binding = 12) readonly buffer DrawRank { uint drawRank[]; };
uniform int uMaxLayers;         // 0: unlimited (R2)
uniform int uAllAreTargets;     // 1: every object not flagged distractor or impenetrable is a target

const uint kRoleTarget = 4u, kRoleDistractor = 8u, kRoleImpenetrable = 16u;  // Role flags
#define MAX_SURFACES 64       // distinct objects per pixel; farther ones beyond this are dropped

uint gSurface[MAX_SURFACES];
int gSurfaceCount;
bool gTruncated;  // layer control cut the list: gSurface[0] is drawn opaque

uint objectOf(uint f) { return sorted[fragWord(f, TLAB_OFF_IDS)] & 0xFFFFu; }
float depthOf(uint f) { return uintBitsToFloat(sorted[fragWord(f, OFF_DEPTH)]); }
bool isTarget(uint f) {
  uint roles = objects[objectOf(f)].info.x;
  if (uAllAreTargets != 0) return (roles & (kRoleDistractor | kRoleImpenetrable)) == 0u;
  return (roles & kRoleTarget) != 0u;
}

void collectSurfaces(uint base, uint n) {
  uint frag[MAX_SURFACES];
  uint rank[MAX_SURFACES];
  int m = 0;
  // 1. The front-most fragment of each object (the list is sorted front to back).
  for (uint i = 0u; i < n && m < MAX_SURFACES; ++i) {
    uint f = base + i, o = objectOf(f);
    bool seen = false;
    for (int j = 0; j < m && !seen; ++j) seen = objectOf(frag[j]) == o;
    if (seen) continue;
    // 2. Insertion into drawing order (ascending rank).
    uint r = drawRank[o];
    int j = m++;
    while (j > 0 && rank[j - 1] > r) {
      frag[j] = frag[j - 1];
      rank[j] = rank[j - 1];
      --j;
    }
    frag[j] = f;
    rank[j] = r;
  }
  // 3. The Z-test in drawing order: what is drawn has strictly decreasing depth.
  int drawn = 0;
  float zBuffer = 1e30;
  for (int j = 0; j < m; ++j) {
    float z = depthOf(frag[j]);
    if (z < zBuffer) {
      frag[drawn++] = frag[j];
      zBuffer = z;
    }
  }
  // 4. Layer control.
  int first = 0;
  gTruncated = false;
  if (uMaxLayers > 0 && drawn > uMaxLayers + 1) {
    first = drawn - (uMaxLayers + 1);
    gTruncated = true;
  }
  gSurfaceCount = drawn - first;
  for (int k = 0; k < gSurfaceCount; ++k) gSurface[k] = frag[first + k];
}
