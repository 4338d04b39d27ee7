#version 450 core
// The connect pass (Carnecky Sec. 4.4, 5.2, 5.3), in three dispatches, after the sort pass has
// written each list's maxStep = max |d·∇z| along x and along y (the window findNeighbor widens by):
//  TLAB_PHASE 1: each pair of adjacent pixels (A, B) once, by the invocation of A for B to its
//     right and B above it (phases 1 and 2 run only for pixels that hold a fragment: B's links
//     towards an empty A are none, written by B's invocation): walking both lists layer by layer, the geodesic neighbour of every
//     fragment in the other list by the continuity measure ε = wz·εz + wn·εn (Eqs. 1-3), kept only
//     when no other fragment of its own list matches that candidate better (Alg. 2) — where the
//     answer follows from the fragment's own layer and the layers next to it in both lists (the
//     fast path below). Links are kept only when both fragments chose each other (ε is not
//     symmetric: εz uses the first fragment's gradient), so the graph Laplacian of the diffusion
//     is symmetric; with both of a layer's answers at hand that test is settled here, and each
//     link word has one writer. A pair with a link the fast path left UNRESOLVED is appended to a
//     work list, its links written unfiltered;
//  TLAB_PHASE 3: for the listed pairs only, the full bounded search (findNeighbor) of the
//     UNRESOLVED links both ways, then the mutual test over both lists;
//  TLAB_LINK_MASKS (every list at most 32 layers long): phase 1 writes no link word for the pairs
//     it settles, only one bit per layer and pair in the pixel's pair word (a link settled by the
//     fast path joins the same layer of both lists); phase 2 writes each fragment's four links
//     from those bits at once. (On llvmpipe every single-word store is a loop over the lanes: the
//     link words took about a fifth of phase 1 on the 16-layer stack, issue #29.)
//  TLAB_PHASE 2: from each fragment's own (mutual) links, the initial α, constant s (Eq. 4) or
//     adaptive 1 − (1 − s)^(1/n) (Eq. 5), and the boundary conditions of Sec. 5.3 on β and γ with
//     their b flags; with TLAB_LIST_SEEDS, the fragments where β and γ start above 0 (Eq. 9's
//     seeds) in lists for the solve's frontier. It stores only the values no other pass knows
//     already: α only where it varies (TLAB_ADAPTIVE_ALPHA, Eq. 5; Eq. 4's s is one number),
//     β and γ only without the seed lists (with them, a field is 1 at its seeds and 0 elsewhere,
//     which the host writes where there is a seed at all: ops/set_listed.comp).
// Over 300 lines: the phases share ε, the searches and the fast path, so they stay one shader;
// main, over 60 lines, holds one branch per phase (TLAB_PHASE), each of them shorter.
#include "frame/fragment_layout.glsl"
#include "frame/compute_index.glsl"
#include "frame/covered_pixels.glsl"
#include "ops/field_bindings.glsl"
layout(std430, binding = BIND_PIXEL_COUNT) readonly buffer PixelCount { uint pixelCount[]; };
layout(std430, binding = BIND_PIXEL_HEAD) readonly buffer PixelHead { uint pixelHead[]; };
#ifdef TLAB_SORTED_TEXELS
// The sorted records read as a buffer texture (one word a texel): the same words, fetched for all
// lanes at once where the CPU rasterizer reads storage buffers lane by lane.
uniform usamplerBuffer uSortedWords;
uint sortedWord(uint i) { return texelFetch(uSortedWords, int(i)).x; }
#else
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer Sorted { uint sorted[]; };
uint sortedWord(uint i) { return sorted[i]; }
#endif
layout(std430, binding = BIND_LINKS) buffer Links { uvec4 links[]; };
layout(std430, binding = BIND_ALPHA_OUT) writeonly buffer Alpha { float alpha[]; };
#ifdef TLAB_HAS_BETA
layout(std430, binding = BIND_BETA_OUT) writeonly buffer Beta { float beta[]; };
#endif
#ifdef TLAB_HAS_GAMMA
layout(std430, binding = BIND_GAMMA_OUT) writeonly buffer Gamma { float gamma[]; };
#endif
layout(std430, binding = BIND_FLAGS) writeonly buffer Flags { uint flags[]; };
#if TLAB_PHASE == 1 || TLAB_PHASE == 3
// The pairs whose links need the full search: a count, then 2 × pixel A + axis (0: B to the
// right of A, 1: B above). `partial` (TLAB_LINK_MASKS): set where some fragment lacks the link to
// the same layer of an adjacent pixel in the image, or a pair was listed (see phase 1).
layout(std430, binding = BIND_CONNECT_WORK) buffer Work { uint workCount; uint partial; uint workPairs[]; };
#endif
#ifdef TLAB_LINK_MASKS
// Per pixel that holds a fragment, its pairs with the pixel to its right (.x) and the one above
// (.y): bit L set where layer L of both lists link to each other; .z bit i set where pair i was
// listed for phase 3 (its links then are the words of the links buffer, both ways).
#if TLAB_PHASE == 2
// Read by phase 2 as one RGBA32UI texel a pixel (a fetch for all lanes).
uniform usamplerBuffer uPairTexels;
uvec4 pairsOf(uint p) { return texelFetch(uPairTexels, int(p)); }
#else
layout(std430, binding = BIND_CONNECT_PAIRS) writeonly buffer Pairs { uvec4 pairWords[]; };
#endif
#endif
#if TLAB_PHASE != 2
// Per pixel, maxStep along x and y: max |d·∇z| over its list, written by the sort pass as it
// copies the records (buffer/sort.comp), read by phases 1 and 3.
layout(std430, binding = BIND_LIST_STEPS) readonly buffer Steps { vec2 steps[]; };
#endif
#if TLAB_PHASE == 2 && defined(TLAB_LIST_SEEDS)
// The fragments Eq. 9 spreads from (value above 0), for the solve's frontier (ops/spread_frontier.comp).
#ifdef TLAB_HAS_BETA
FRONTIER_LIST(, BIND_SEEDS_BETA, SeedsBeta, betaSeeds);
#endif
#ifdef TLAB_HAS_GAMMA
FRONTIER_LIST(, BIND_SEEDS_GAMMA, SeedsGamma, gammaSeeds);
#endif
#endif
#if TLAB_PHASE == 2 && defined(TLAB_LINK_TEXELS)
// Phase 2 reads a fragment's own 4 links as one texel of an RGBA32UI buffer texture (one fetch
// for all lanes, where llvmpipe reads a storage buffer lane by lane and word by word).
uniform usamplerBuffer uLinkTexels;
uvec4 linksOf(uint f) { return texelFetch(uLinkTexels, int(f)); }
#else
uvec4 linksOf(uint f) { return links[f]; }
#endif
#ifdef TLAB_GRADIENT_PAIR
// The storage buffer's records two words at a time: the gradient in one load (stride and offset
// are even). (Read as RG32UI texels instead, the pass executed more instructions than with two
// R32UI fetches, issue #29: the texel path reads the gradient word by word.)
layout(std430, binding = BIND_FRAGS_SORTED) readonly buffer SortedPairs { uvec2 sortedPairs[]; };
uvec2 sortedPair(uint i) { return sortedPairs[i]; }
#endif
uniform int uWidth;
uniform int uHeight;
uniform float uObjectRadius;  // r_obj of Eq. 1
uniform float uWz;
uniform float uGapScale;     // wz / r_obj, for beyond
uniform float uWn;
uniform float uS;

float depthOf(uint f) { return uintBitsToFloat(sortedWord(fragWord(f, OFF_DEPTH))); }

// What ε reads of a fragment, loaded once per fragment rather than once per comparison.
struct Surfel {
  float z;
  vec2 g;      // ∇z per pixel
  vec3 n;
  uint comp;   // connected component (0 without ids)
};
// The surfel of a record's words: depth, ∇z, normal and ids (0 where records carry no ids).
Surfel surfelOf(uint depthWord, uvec2 gradientWords, uint normalWord, uint idsWord) {
  return Surfel(uintBitsToFloat(depthWord), uintBitsToFloat(gradientWords), decodeNormal(normalWord), (idsWord >> 16) & 0x7FFFu);
}
#ifdef TLAB_SORTED_QUADS
// The record's quads of words as RGBA32UI texels (records padded to quads): a surfel in 2 fetches
// where it takes 5 words. llvmpipe fetches such a texel with one 16-byte load a lane, an R32UI
// texel with a gather, and phase 1 waits on these loads (its neighbours' lists are far apart in
// memory): natively on the 16-layer stack the pass took about 13 % less time, while it executed
// about 1 % more instructions (issue #29, twelfth round).
uniform usamplerBuffer uSortedQuads;
Surfel surfel(uint f) {
  uvec4 q[TLAB_RECORD_QUADS];
  for (uint k = 0u; k < TLAB_RECORD_QUADS; ++k) q[k] = texelFetch(uSortedQuads, int(f * TLAB_RECORD_QUADS + k));
#ifdef TLAB_HAS_IDS
  uint ids = quadWord(q, TLAB_OFF_IDS);
#else
  uint ids = 0u;
#endif
  const uint g = TLAB_OFF_DEPTH_GRADIENT;
  return surfelOf(quadWord(q, OFF_DEPTH), uvec2(quadWord(q, g), quadWord(q, g + 1u)), quadWord(q, TLAB_OFF_NORMAL), ids);
}
#else
// The record word by word (its gradient in one load where TLAB_GRADIENT_PAIR).
Surfel surfel(uint f) {
  uint g = fragWord(f, TLAB_OFF_DEPTH_GRADIENT);
#ifdef TLAB_GRADIENT_PAIR
  uvec2 gradient = sortedPair(g >> 1);
#else
  uvec2 gradient = uvec2(sortedWord(g), sortedWord(g + 1u));
#endif
#ifdef TLAB_HAS_IDS
  uint ids = sortedWord(fragWord(f, TLAB_OFF_IDS));
#else
  uint ids = 0u;
#endif
  return surfelOf(sortedWord(fragWord(f, OFF_DEPTH)), gradient, sortedWord(fragWord(f, TLAB_OFF_NORMAL)), ids);
}
#endif

// ε(i, j) for fragment i and fragment j one pixel away in direction d (Eqs. 1-3); fragments of
// different connected components are never neighbours.
// normalDot is n_i·n_j, given where the caller has it already (phase 1's fast path: the product
// is symmetric, so a pair of layers met from both ends takes it once; the same float operations
// in the same order either way, so the same bits).
float continuityOfDot(Surfel i, Surfel j, ivec2 d, float normalDot) {
  if (i.comp != j.comp) return 1.0 / 0.0;
  float predicted = i.z + dot(vec2(d), i.g);
  float epsZ = abs(predicted - j.z) / uObjectRadius;  // Eq. 1
  float epsN = 1.0 - normalDot;                       // Eq. 2
  return uWz * epsZ + uWn * epsN;                     // Eq. 3
}
float continuity(Surfel i, Surfel j, ivec2 d) { return continuityOfDot(i, j, d, dot(i.n, j.n)); }

const ivec2 kDirections[4] = ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));

// ε ≥ wz·εz because εn = 1 − n_i·n_j ≥ 0 (up to rounding: kEpsNSlack covers a dot product of two
// unit normals a few ulps above 1). So once wz·|Δz|/r_obj passes the best ε found, no fragment
// further away in depth can match better: lists are sorted by depth, and the searches below walk
// outwards from the predicted depth and stop there. Same result as comparing all pairs (ties go to
// the lower index, as in a front-to-back scan), in O(log n + matches) instead of O(n) per query.
// (wz·|Δz|/r_obj as |Δz|·(wz/r_obj), a multiplication where a division costs several: a few ulps
// apart, far inside the slack of the last two terms, so still a bound.)
const float kEpsNSlack = 1e-4;
bool beyond(float depthGap, float bestEps) {
  return uGapScale * depthGap - uWn * kEpsNSlack > bestEps + abs(bestEps) * 1e-5;
}

// First index in [head, head + count) whose depth is ≥ z. Neighbouring lists mostly hold the
// same surfaces in the same order, so the answer is tried at `hint` (the layer being matched)
// first, and found by binary search over the sorted list otherwise.
bool isLowerBound(uint head, uint count, float z, uint k) {
  return k <= count && (k == count || depthOf(head + k) >= z) && (k == 0u || depthOf(head + k - 1u) < z);
}
uint lowerBound(uint head, uint count, float z, uint hint) {
  if (isLowerBound(head, count, z, hint)) return hint;
  uint lo = 0u, hi = count;
  while (lo < hi) {
    uint mid = (lo + hi) >> 1;
    if (depthOf(head + mid) < z) lo = mid + 1u;
    else hi = mid;
  }
  return lo;
}

// Keeps j when it matches a better than the best so far (lower index on a tie), with its record.
void consider(Surfel a, uint j, ivec2 d, inout uint best, inout float bestEps, inout Surfel bestSurfel) {
  Surfel sj = surfel(j);
  float e = continuity(a, sj, d);
  if (e < bestEps || (e == bestEps && e < 1.0 / 0.0 && j < best)) {
    bestEps = e;
    best = j;
    bestSurfel = sj;
  }
}

// The best candidate for a among pixel q's list (Alg. 2's first half).
uint bestCandidate(Surfel a, uint layer, uint headB, uint countB, ivec2 d, out float bestEps, out Surfel bestSurfel) {
  uint best = NO_NEIGHBOR;
  bestEps = 1.0 / 0.0;
  bestSurfel = a;
  float predicted = a.z + dot(vec2(d), a.g);
  uint start = lowerBound(headB, countB, predicted, min(layer, countB));
  for (uint k = start; k < countB && !beyond(depthOf(headB + k) - predicted, bestEps); ++k)
    consider(a, headB + k, d, best, bestEps, bestSurfel);
  for (uint k = start; k > 0u && !beyond(predicted - depthOf(headB + k - 1u), bestEps); --k)
    consider(a, headB + k - 1u, d, best, bestEps, bestSurfel);
  return best;
}

// Alg. 2: the best candidate for fragment a among the list of pixel q, unless some other fragment
// of a's own list is an even better match for that candidate (the relation must be mutual). The
// other fragments predict with their own gradients, so their window in depth is widened by
// maxStep = max |d·∇z| over a's list.
uint findNeighbor(uint a, Surfel sa, uint headA, uint countA, uint headB, uint countB, ivec2 d, float maxStep) {
#ifdef TLAB_ALL_PAIRS
  // The reference: every pair, as Alg. 2 is written (tests check the search above against it).
  uint best = NO_NEIGHBOR;
  float bestEps = 1.0 / 0.0;
  for (uint k = 0u; k < countB; ++k) {
    float e = continuity(sa, surfel(headB + k), d);
    if (e < bestEps) {
      bestEps = e;
      best = headB + k;
    }
  }
  if (best == NO_NEIGHBOR) return NO_NEIGHBOR;
  Surfel sb = surfel(best);
  for (uint k = 0u; k < countA; ++k)
    if (headA + k != a && continuity(surfel(headA + k), sb, d) < bestEps) return NO_NEIGHBOR;
  return best;
#else
  float bestEps;
  Surfel sb;
  uint best = bestCandidate(sa, a - headA, headB, countB, d, bestEps, sb);
  if (best == NO_NEIGHBOR) return NO_NEIGHBOR;
  uint start = lowerBound(headA, countA, sb.z, a - headA);
  for (uint k = start; k < countA && !beyond(depthOf(headA + k) - sb.z - maxStep, bestEps); ++k)
    if (headA + k != a && continuity(surfel(headA + k), sb, d) < bestEps) return NO_NEIGHBOR;
  for (uint k = start; k > 0u && !beyond(sb.z - depthOf(headA + k - 1u) - maxStep, bestEps); --k)
    if (headA + k - 1u != a && continuity(surfel(headA + k - 1u), sb, d) < bestEps) return NO_NEIGHBOR;
  return best;
#endif
}

bool inside(ivec2 q) { return q.x >= 0 && q.y >= 0 && q.x < uWidth && q.y < uHeight; }

// A link the fast path could not settle; phase 3 replaces it (fragment indices never reach it).
const uint UNRESOLVED = 0xFFFFFFFEu;

// The fast path of findNeighbor for fragment a = layer L of its list (sa; prev and next are layers
// L - 1 and L + 1 when they exist) towards the list B of an adjacent pixel, of which it knows
// layer L (sb, when L < countB) and the depths of layers L - 1 and L + 1 (bPrevZ, bNextZ). It
// returns what findNeighbor returns whenever that follows from these layers alone — then
// NO_NEIGHBOR or headB + L — else UNRESOLVED. Both halves rest on the bound that makes
// findNeighbor's search exact (see beyond): a layer whose depth gap is beyond ε cannot match
// better, nor can any layer further out on the same side, the list being sorted by depth.
//  - The best candidate: layer L of B, when its ε is finite and layers L ± 1 of B lie on either
//    side of the predicted depth and are beyond that ε (or do not exist).
//  - The mutual test: findNeighbor visits the layers k of a's own list whose gap |z_k - z_b| -
//    maxStep is not beyond ε (a contiguous range, the gap being V-shaped in k). Layers L ± 1 are
//    tested here; the rest is settled when L ± 1 lie on the far side of b and are beyond (all
//    layers further out then are too), or when the list ends there.
// The normals' products n_a·n_b, n_next·n_b and n_prev·n_b come from the caller (dots: x, y, z).
uint fastNeighbor(Surfel sa, uint L, Surfel prev, Surfel next, uint n, uint headB, uint countB, Surfel sb,
                  float bPrevZ, float bNextZ, ivec2 d, float maxStep, vec3 dots) {
#ifdef TLAB_ALL_PAIRS
  return countB == 0u ? NO_NEIGHBOR : UNRESOLVED;  // (every pair is searched in phase 3)
#else
  // Written without early returns: llvmpipe runs every branch under a lane mask, so the
  // conditions are combined and one answer selected, in the order the cases take precedence.
  float predicted = sa.z + dot(vec2(d), sa.g);
  float e = continuityOfDot(sa, sb, d, dots.x);
  bool unresolved = L >= countB || !(e < 1.0 / 0.0) ||
                    (L + 1u < countB && !(bNextZ >= predicted && beyond(bNextZ - predicted, e))) ||
                    (L > 0u && !(bPrevZ <= predicted && beyond(predicted - bPrevZ, e)));
  // The mutual test over the own list (Alg. 2's second half).
  bool hasNext = L + 1u < n, hasPrev = L > 0u;
  bool nextFar = !hasNext || next.z >= sb.z;
  bool nextVisited = hasNext && !beyond(nextFar ? next.z - sb.z - maxStep : sb.z - next.z - maxStep, e);
  bool prevFar = !hasPrev || prev.z <= sb.z;
  bool prevVisited = hasPrev && !beyond(prevFar ? sb.z - prev.z - maxStep : prev.z - sb.z - maxStep, e);
  bool beaten = (nextVisited && continuityOfDot(next, sb, d, dots.y) < e) || (prevVisited && continuityOfDot(prev, sb, d, dots.z) < e);
  bool forwardDone = L + 2u >= n || (nextFar && !nextVisited);
  bool backwardDone = L < 2u || (prevFar && !prevVisited);
  uint settled = beaten ? NO_NEIGHBOR : forwardDone && backwardDone ? headB + L : UNRESOLVED;
  return countB == 0u ? NO_NEIGHBOR : unresolved ? UNRESOLVED : settled;  // (no list: also beyond the image edge)
#endif
}

// A is paired with the pixel to its right (axis 0) and the one above it (axis 1). For axis i the
// link A -> B is direction 2i + 1 and B -> A direction 2i (kDirections).
const ivec2 kPairDirections[2] = ivec2[2](ivec2(1, 0), ivec2(0, 1));

// What phase 1 writes for fragment a = layer L of A, given the fast path's answers for a (towards
// B: fa) and for layer L of B (towards A: fb). fa is headB + L only where layer L of B exists, and
// fb is then NO_NEIGHBOR, UNRESOLVED or a itself: the link is kept when both chose each other,
// dropped when b chose nobody, and left for phase 3 (unfiltered) when b's answer is UNRESOLVED.
uint settledLink(uint a, uint fa, uint fb) {
  bool chosen = fa < UNRESOLVED;  // a fragment
  return chosen && fb != UNRESOLVED && fb != a ? NO_NEIGHBOR : fa;
}

#ifdef TLAB_PIXEL_TEXELS
// The per-pixel counts, heads and maxSteps read as buffer textures (one fetch for all lanes).
uniform usamplerBuffer uPixelCounts;  // R32UI
uniform usamplerBuffer uPixelHeads;   // R32UI
uniform samplerBuffer uListSteps;     // RG32F
uint countOf(uint p) { return texelFetch(uPixelCounts, int(p)).x; }
uint headOf(uint p) { return texelFetch(uPixelHeads, int(p)).x; }
#if TLAB_PHASE != 2
vec2 stepOf(uint p) { return texelFetch(uListSteps, int(p)).xy; }
#endif
#else
uint countOf(uint p) { return pixelCount[p]; }
uint headOf(uint p) { return pixelHead[p]; }
#if TLAB_PHASE != 2
vec2 stepOf(uint p) { return steps[p]; }
#endif
#endif

// The pixel index of q, or 0 beyond the image (a CPU rasterizer runs the reads of both sides of a
// branch under a mask: every lane's index stays in range).
uint indexAt(ivec2 q) { return inside(q) ? uint(q.y * uWidth + q.x) : 0u; }

// The number of layers at q (none beyond the image).
uint countAt(ivec2 q) {
  uint c = countOf(indexAt(q));
  return inside(q) ? c : 0u;
}

// Per pixel: how many layers, where they start, and maxStep (zero for an empty list or one
// beyond the image, whose lists are empty).
struct List {
  uint head, count;
  vec2 step;
};
List listAt(ivec2 q) {
  List l;
  l.head = 0u;
  l.count = 0u;
  l.step = vec2(0.0);
  if (!inside(q)) return l;
  uint p = indexAt(q);
  l.count = countOf(p);
#if TLAB_PHASE != 2
  if (l.count > 0u) {
    l.head = headOf(p);
    l.step = stepOf(p);
  }
#endif
  return l;
}

void main() {
#if TLAB_PHASE == 3
  uint item = linearInvocation();
  if (item >= workCount) return;
  uint pixel = workPairs[item] >> 1u;
#else
  uint pixel;  // phases 1 and 2 run for the pixels that hold a fragment only
  if (!coveredInvocation(pixel)) return;
#endif
  uint n = countOf(pixel);
  uint head = headOf(pixel);
  ivec2 xy = ivec2(int(pixel % uint(uWidth)), int(pixel / uint(uWidth)));
#if TLAB_PHASE == 1
  // Walks the three lists (A, B to its right, B above) with the layers next to the current one in
  // registers: each layer's record is read once by this invocation.
  List a = List(head, n, n > 0u ? stepOf(pixel) : vec2(0.0));
  List b[2] = List[2](listAt(xy + kPairDirections[0]), listAt(xy + kPairDirections[1]));
  uint layers = max(n, max(b[0].count, b[1].count));
  Surfel aPrev, aCur, aNext, bPrev[2], bCur[2], bNext[2];
  aNext = n > 0u ? surfel(head) : Surfel(0.0, vec2(0.0), vec3(0.0), 0u);
  aCur = aNext;
  for (int i = 0; i < 2; ++i) {
    bNext[i] = b[i].count > 0u ? surfel(b[i].head) : aNext;
    bCur[i] = bNext[i];
  }
  bool listed[2] = bool[2](false, false);
  // Per pair, the normals' products layer L + 1 of each list takes with layer L of the other,
  // which the next layer's tests of layer L + 1 against its previous one take again.
  float aNextDotB[2] = float[2](0.0, 0.0), bNextDotA[2] = float[2](0.0, 0.0);
#ifdef TLAB_LINK_MASKS
  // Bit L: layer L of A links to layer L of B (sameA), and the other way (sameB). A pair with no
  // UNRESOLVED answer links both ways or not at all, so sameA is its pair word.
  uint sameA[2] = uint[2](0u, 0u), sameB[2] = uint[2](0u, 0u);
#else
  bool leftEmpty = countAt(xy - kPairDirections[0]) == 0u, belowEmpty = countAt(xy - kPairDirections[1]) == 0u;
#endif
  for (uint L = 0u; L < layers; ++L) {
    aPrev = aCur;
    aCur = aNext;
    if (L + 1u < n) aNext = surfel(head + L + 1u);
    for (int i = 0; i < 2; ++i) {
      bPrev[i] = bCur[i];
      bCur[i] = bNext[i];
      if (L + 1u < b[i].count) bNext[i] = surfel(b[i].head + L + 1u);
      // n_prev·n_cur of this layer is n_next·n_cur of the last (the registers shifted by one).
      float aPrevDotB = bNextDotA[i], bPrevDotA = aNextDotB[i];
      float curDot = dot(aCur.n, bCur[i].n);
      aNextDotB[i] = dot(aNext.n, bCur[i].n);
      bNextDotA[i] = dot(bNext[i].n, aCur.n);
      uint fa = NO_NEIGHBOR, fb = NO_NEIGHBOR;
      if (L < n)
        fa = fastNeighbor(aCur, L, aPrev, aNext, n, b[i].head, b[i].count, bCur[i], bPrev[i].z, bNext[i].z,
                          kPairDirections[i], a.step[i], vec3(curDot, aNextDotB[i], aPrevDotB));
      if (L < b[i].count)
        fb = fastNeighbor(bCur[i], L, bPrev[i], bNext[i], b[i].count, head, n, aCur, aPrev.z, aNext.z,
                          -kPairDirections[i], b[i].step[i], vec3(curDot, bNextDotA[i], bPrevDotA));
      listed[i] = listed[i] || fa == UNRESOLVED || fb == UNRESOLVED;
#ifdef TLAB_LINK_MASKS
      if (L < n && settledLink(head + L, fa, fb) == b[i].head + L) sameA[i] |= 1u << L;
      if (L < b[i].count && settledLink(b[i].head + L, fb, fa) == head + L) sameB[i] |= 1u << L;
#else
      if (L < n) links[head + L][2 * i + 1] = settledLink(head + L, fa, fb);
      if (L < b[i].count) links[b[i].head + L][2 * i] = settledLink(b[i].head + L, fb, fa);
#endif
    }
#ifndef TLAB_LINK_MASKS
    // No pair writes these beyond the left and bottom edges, nor where the pixel there is empty
    // (no invocation for it).
    if (L < n && leftEmpty) links[head + L][0] = NO_NEIGHBOR;
    if (L < n && belowEmpty) links[head + L][2] = NO_NEIGHBOR;
#endif
  }
#ifdef TLAB_LINK_MASKS
  // A listed pair's links are words for phase 3, both ways: the same layer where the fast path
  // chose it, UNRESOLVED for the rest. (The fast path's other answers are findNeighbor's too, so
  // phase 3's search gives them again: the same links as keeping them.)
  for (int i = 0; i < 2; ++i)
    for (uint L = 0u; listed[i] && L < layers; ++L) {
      if (L < n) links[head + L][2 * i + 1] = (sameA[i] & (1u << L)) != 0u ? b[i].head + L : UNRESOLVED;
      if (L < b[i].count) links[b[i].head + L][2 * i] = (sameB[i] & (1u << L)) != 0u ? head + L : UNRESOLVED;
    }
  pairWords[pixel] = uvec4(sameA[0], sameA[1], (listed[0] ? 1u : 0u) | (listed[1] ? 2u : 0u), 0u);
  // Whether this pixel's fragments and those of its pairs link to the same layer all round: both
  // lists of each pair in the image as long and every layer linked, and no empty pixel to the
  // left or below in the image (whose pair no invocation settles). Where that holds for every
  // pixel, phase 2 has nothing to find: every fragment has its 4 neighbours (or the image edge),
  // so no silhouette, no halo and no fixed value, and the host may leave it out (issue #29).
  // (Asked only until some pixel answered no: then one atomic, not one a pixel, and no more reads.)
  if (partial == 0u) {
    uint all = n >= 32u ? 0xFFFFFFFFu : (1u << n) - 1u;
    bool whole = !listed[0] && !listed[1];
    for (int i = 0; i < 2; ++i) {
      whole = whole && (!inside(xy + kPairDirections[i]) || (b[i].count == n && sameA[i] == all));
      whole = whole && (!inside(xy - kPairDirections[i]) || countAt(xy - kPairDirections[i]) > 0u);
    }
    if (!whole) atomicOr(partial, 1u);
  }
#endif
  for (int i = 0; i < 2; ++i)
    if (listed[i]) workPairs[atomicAdd(workCount, 1u)] = 2u * pixel + uint(i);
#elif TLAB_PHASE == 3
  int i = int(workPairs[item] & 1u);
  List a = listAt(xy), b = listAt(xy + kPairDirections[i]);
  ivec2 d = kPairDirections[i];
  int ka = 2 * i + 1, kb = 2 * i;
  for (uint L = 0u; L < a.count; ++L)
    if (links[a.head + L][ka] == UNRESOLVED)
      links[a.head + L][ka] = findNeighbor(a.head + L, surfel(a.head + L), a.head, a.count, b.head, b.count, d, a.step[i]);
  for (uint L = 0u; L < b.count; ++L)
    if (links[b.head + L][kb] == UNRESOLVED)
      links[b.head + L][kb] = findNeighbor(b.head + L, surfel(b.head + L), b.head, b.count, a.head, a.count, -d, b.step[i]);
  // The mutual test, in place: a link kept is kept by its other end too, so a word already
  // tested reads as before wherever the answer depends on it.
  for (uint L = 0u; L < a.count; ++L) {
    uint j = links[a.head + L][ka];
    if (j != NO_NEIGHBOR && links[j][kb] != a.head + L) links[a.head + L][ka] = NO_NEIGHBOR;
  }
  for (uint L = 0u; L < b.count; ++L) {
    uint j = links[b.head + L][kb];
    if (j != NO_NEIGHBOR && links[j][ka] != b.head + L) links[b.head + L][kb] = NO_NEIGHBOR;
  }
#else
  if (n == 0u) return;
#ifdef TLAB_ADAPTIVE_ALPHA
  float alphaInit = 1.0 - pow(1.0 - uS, 1.0 / float(n));  // Eq. 5 (Eq. 4's s is not stored)
#endif
  uvec4 qHead = uvec4(0u);  // heads of the adjacent lists, to turn a link into a layer
  uint outside = 0u;        // adjacent pixels beyond the image edge
  for (int k = 0; k < 4; ++k) {
    ivec2 q = xy + kDirections[k];
    if (inside(q)) qHead[k] = headOf(indexAt(q));
    else ++outside;
  }
#ifdef TLAB_LINK_MASKS
  // The pair words of this pixel (its links right and up) and of the pixels to its left and
  // below (their pairs with this one); none where such a pixel holds no list (or is beyond the
  // edge), whose word no invocation wrote this frame.
  uvec4 ownPairs = pairsOf(pixel);
  ivec2 leftQ = xy + kDirections[0], belowQ = xy + kDirections[2];
  bool leftHasList = countAt(leftQ) > 0u, belowHasList = countAt(belowQ) > 0u;
  uvec4 leftPairs = pairsOf(indexAt(leftQ)), belowPairs = pairsOf(indexAt(belowQ));
  // Whether any of the four pairs was listed: only then does a link come from the words.
  bool anyListed = (ownPairs.z | (leftHasList ? leftPairs.z & 1u : 0u) | (belowHasList ? belowPairs.z & 2u : 0u)) != 0u;
#endif
  // Seeds are listed 32 layers at a time: one atomic per list and chunk with a seed
  // (FRONTIER_RESERVE says why).
  for (uint chunk = 0u; chunk < n; chunk += 32u) {
  uint betaMask = 0u, gammaMask = 0u;  // the chunk's layers where β, γ start above 0
  for (uint layer = chunk; layer < min(n, chunk + 32u); ++layer) {
    uint f = head + layer;
#ifdef TLAB_LINK_MASKS
    // Each link from its pair's bit, or the word phase 1 (and 3) wrote where the pair was listed.
    uvec4 link = uvec4(NO_NEIGHBOR);
    if (anyListed) link = links[f];
    uint bit = 1u << layer;
    link[1] = (ownPairs.z & 1u) != 0u ? link[1] : (ownPairs.x & bit) != 0u ? qHead[1] + layer : NO_NEIGHBOR;
    link[3] = (ownPairs.z & 2u) != 0u ? link[3] : (ownPairs.y & bit) != 0u ? qHead[3] + layer : NO_NEIGHBOR;
    link[0] = !leftHasList ? NO_NEIGHBOR : (leftPairs.z & 1u) != 0u ? link[0] : (leftPairs.x & bit) != 0u ? qHead[0] + layer : NO_NEIGHBOR;
    link[2] = !belowHasList ? NO_NEIGHBOR : (belowPairs.z & 2u) != 0u ? link[2] : (belowPairs.y & bit) != 0u ? qHead[2] + layer : NO_NEIGHBOR;
    links[f] = link;
#else
    const uvec4 link = linksOf(f);
#endif
    uint found = 0u;
    bool nextToSilhouette = false, underSilhouette = false;
    for (int k = 0; k < 4; ++k) {
      uint j = link[k];
      if (j == NO_NEIGHBOR) continue;
      ++found;
      uint neighborLayer = j - qHead[k];
      nextToSilhouette = nextToSilhouette || layer < neighborLayer;
      underSilhouette = underSilhouette || layer > neighborLayer;
    }
    // Sec. 5.2 initial conditions, then Sec. 5.3 boundary conditions.
    float b = 0.0, g = 0.0;
    uint free = FREE_ALPHA | FREE_BETA | FREE_GAMMA;
    // A neighbour beyond the image edge is unknown, not missing: the frame cuts the surface, it
    // is no silhouette (issue #20: zoomed-in views drew the frame as one).
    if (found + outside < 4u) { b = 1.0; free &= ~FREE_BETA; }  // boundary or silhouette (red)
    if (nextToSilhouette) { g = 1.0; free &= ~FREE_GAMMA; }  // beside an occluding edge (blue)
    if (underSilhouette) { b = 0.0; free &= ~FREE_BETA; }    // right under a silhouette (green)
#ifdef TLAB_ADAPTIVE_ALPHA
    alpha[f] = alphaInit;
#endif
#if defined(TLAB_HAS_BETA) && !defined(TLAB_LIST_SEEDS)
    beta[f] = b;
#endif
#ifdef TLAB_HAS_BETA
    if (b > 0.0) betaMask |= 1u << (layer - chunk);
#endif
#ifdef TLAB_HAS_GAMMA
#ifndef TLAB_LIST_SEEDS
    gamma[f] = g;
#endif
    if (g > 0.0) gammaMask |= 1u << (layer - chunk);
#endif
    flags[f] = free;
  }
#ifdef TLAB_LIST_SEEDS
#ifdef TLAB_HAS_BETA
  FRONTIER_APPEND_LAYERS(betaSeeds, betaMask, head + chunk);
#endif
#ifdef TLAB_HAS_GAMMA
  FRONTIER_APPEND_LAYERS(gammaSeeds, gammaMask, head + chunk);
#endif
#endif
  }
#endif
}
