#include "renderer/ops/fast_links.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "core/parallel_shares.hpp"

// 32-byte vectors are passed only between functions inlined into one another (always_inline),
// all of them compiled for AVX2 where they are (see settleRows): no ABI crosses here (the
// build gives this file -Wno-psabi).

namespace tlab::render {

namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;        // NO_NEIGHBOR of ops/field_bindings.glsl
constexpr std::uint32_t kUnresolved = 0xFFFFFFFEu;  // UNRESOLVED of ops/connect.comp
constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kEpsNSlack = 1e-4f;  // ops/connect.comp's, for beyond
constexpr int kMaxLanes = 8;

#define TLAB_INLINE __attribute__((always_inline)) inline

// N lanes, as GCC's vector extension (SSE, or AVX2 where settleRows is built for it): the same IEEE
// operations lane by lane as one at a time, so each lane's bits are the scalar code's (no
// contraction: -std=c++20, and no FMA instructions).
template <int N>
struct Lanes {
  typedef float F __attribute__((vector_size(4 * N)));
  typedef std::int32_t I __attribute__((vector_size(4 * N)));
  static TLAB_INLINE F load(const float* p) {
    F v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static TLAB_INLINE I load(const std::int32_t* p) {
    I v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static TLAB_INLINE void store(std::int32_t* p, I v) { std::memcpy(p, &v, sizeof v); }
  static TLAB_INLINE void store(float* p, F v) { std::memcpy(p, &v, sizeof v); }
  static TLAB_INLINE F splat(float x) { return F{} + x; }
  static TLAB_INLINE I all() { return I{} - 1; }
  static TLAB_INLINE F absolute(F v) { return F(I(v) & 0x7FFFFFFF); }
};

enum Plane { kZ, kGx, kGy, kNx, kNy, kNz, kPlanes };

struct Weights {
  float r, wz, gapScale, wn, wnSlack;
};

// One row's layer planes (FastLinkRows::Row), decoded from the sorted records.
class RowPlanes {
 public:
  RowPlanes(FastLinkRows::Row& row, std::size_t paddedWidth, std::uint32_t layers)
      : row_(row), pitch_(paddedWidth), layers_(layers) {
    const std::size_t cells = std::size_t(layers) * paddedWidth;
    // Never shrunk, and zero where new: every cell holds 0 or a value decoded for some list.
    if (row.planes.size() < kPlanes * cells) row.planes.resize(kPlanes * cells, 0.0f);
    if (row.comps.size() < cells) row.comps.resize(cells, 0);
    row.counts.resize(paddedWidth);
    row.heads.resize(paddedWidth);
    row.stepX.resize(paddedWidth);
    row.stepY.resize(paddedWidth);
  }
  const float* plane(Plane p, std::uint32_t layer) const { return row_.planes.data() + (std::size_t(p) * layers_ + layer) * pitch_; }
  float* plane(Plane p, std::uint32_t layer) { return row_.planes.data() + (std::size_t(p) * layers_ + layer) * pitch_; }
  const std::int32_t* comps(std::uint32_t layer) const { return row_.comps.data() + std::size_t(layer) * pitch_; }
  const std::int32_t* counts() const { return row_.counts.data(); }
  const std::int32_t* heads() const { return row_.heads.data(); }
  std::size_t pitch() const { return pitch_; }
  const float* stepX() const { return row_.stepX.data(); }
  const float* stepY() const { return row_.stepY.data(); }
  int first = 0, last = -1;  // the row's covered columns

  // Row y of the grid (no list beyond the image).
  template <int N>
  TLAB_INLINE void load(const CoveredGrid& grid, const SortedSurfels& s, int y) {
    std::fill(row_.counts.begin(), row_.counts.end(), 0);
    first = grid.width;
    last = -1;
    if (y >= grid.height) return;
    std::uint32_t longest = 0;
    // Locals: the stores below (int32 among them) would otherwise make the compiler reload these.
    const std::size_t planeCells = std::size_t(layers_) * pitch_, pitch = pitch_, stride = s.stride;
    const std::uint32_t gradient = s.gradientOffset, normal = s.normalOffset, ids = s.idsOffset;
    const bool hasIds = s.hasIds;
    const std::uint32_t *counts = grid.counts + std::size_t(y) * grid.width, *heads = grid.heads + std::size_t(y) * grid.width;
    const glm::vec2* steps = s.steps + std::size_t(y) * grid.width;
    const std::uint32_t* words = s.words;
    float *z = row_.planes.data() + kZ * planeCells, *gx = z + (kGx - kZ) * planeCells, *gy = z + (kGy - kZ) * planeCells,
          *nx = z + (kNx - kZ) * planeCells;
    std::int32_t *rowCounts = row_.counts.data(), *rowHeads = row_.heads.data(), *comps = row_.comps.data();
    float *stepX = row_.stepX.data(), *stepY = row_.stepY.data();
    for (int x = 0; x < grid.width; ++x) {
      const std::uint32_t n = counts[x];
      rowCounts[x] = std::int32_t(n);
      if (n == 0) continue;
      first = std::min(first, x);
      last = x;
      longest = std::max(longest, n);
      rowHeads[x] = std::int32_t(heads[x]);
      stepX[x] = steps[x].x;
      stepY[x] = steps[x].y;
      const std::uint32_t* record = words + std::size_t(heads[x]) * stride;
      for (std::size_t at = std::size_t(x), end = at + n * pitch; at < end; at += pitch, record += stride) {
        z[at] = std::bit_cast<float>(record[0]);
        gx[at] = std::bit_cast<float>(record[gradient]);
        gy[at] = std::bit_cast<float>(record[gradient + 1]);
        nx[at] = std::bit_cast<float>(record[normal]);  // the word, decoded below
        comps[at] = hasIds ? std::int32_t((record[ids] >> 16) & 0x7FFFu) : 0;
      }
    }
    for (std::uint32_t layer = 0; layer < longest; ++layer)
      for (int x = first; x <= last; x += N) decodeNormals<N>(layer, x);
  }

 private:
  // The normal words of N cells decoded in place: frame/fragment_layout.glsl's decodeNormal
  // (render::decodeNormal) lane by lane. Cells beyond a list's end decode whatever word they
  // hold: a unit normal too, never read.
  template <int N>
  TLAB_INLINE void decodeNormals(std::uint32_t layer, int x) {
    using V = Lanes<N>;
    using F = typename V::F;
    using I = typename V::I;
    float *nx = plane(kNx, layer) + x, *ny = plane(kNy, layer) + x, *nz = plane(kNz, layer) + x;
    const I word = I(V::load(nx));
    // unpackSnorm2x16: clamp(int16 / 32767, -1, 1), low half first.
    const auto component = [](const I& bits) {
      const F v = __builtin_convertvector(bits, F) / 32767.0f;
      const F lo = v < -1.0f ? V::splat(-1.0f) : v;
      return 1.0f < lo ? V::splat(1.0f) : lo;
    };
    const F ex = component((word << 16) >> 16), ey = component(word >> 16);
    const F z = 1.0f - V::absolute(ex) - V::absolute(ey);
    const I wrap = z < 0.0f;  // octahedralWrap
    const F x1 = wrap ? (1.0f - V::absolute(ey)) * (ex >= 0.0f ? V::splat(1.0f) : V::splat(-1.0f)) : ex;
    const F y1 = wrap ? (1.0f - V::absolute(ex)) * (ey >= 0.0f ? V::splat(1.0f) : V::splat(-1.0f)) : ey;
    const F length2 = x1 * x1 + y1 * y1 + z * z;  // glm::normalize: v * (1 / sqrt(dot(v, v)))
    F root{};
    for (int j = 0; j < N; ++j) root[j] = std::sqrt(length2[j]);
    const F inverse = 1.0f / root;
    V::store(nx, x1 * inverse);
    V::store(ny, y1 * inverse);
    V::store(nz, z * inverse);
  }

  FastLinkRows::Row& row_;
  std::size_t pitch_;
  std::uint32_t layers_;
};

// Layer `layer` of N adjacent pixels from column x on.
template <int N>
struct Surfels {
  typename Lanes<N>::F z, gx, gy, n[3];
  typename Lanes<N>::I comp;
};
template <int N>
TLAB_INLINE Surfels<N> surfelsAt(const RowPlanes& row, std::uint32_t layer, int x) {
  using V = Lanes<N>;
  return {V::load(row.plane(kZ, layer) + x),
          V::load(row.plane(kGx, layer) + x),
          V::load(row.plane(kGy, layer) + x),
          {V::load(row.plane(kNx, layer) + x), V::load(row.plane(kNy, layer) + x), V::load(row.plane(kNz, layer) + x)},
          V::load(row.comps(layer) + x)};
}

// What ε reads of a fragment: depth, the depth it predicts one pixel on (z + d·∇z), component.
template <int N>
struct Predicting {
  typename Lanes<N>::F z, predicted;
  typename Lanes<N>::I comp;
};
// d = ±x or ±y (connect.comp's dot(vec2(d), ∇z): the zero component adds nothing).
template <int N>
TLAB_INLINE Predicting<N> towards(const Surfels<N>& s, int axis, bool negative) {
  const auto g = axis == 0 ? s.gx : s.gy;
  return {s.z, negative ? s.z - g : s.z + g, s.comp};
}

// ε(i, j) with n_i·n_j given (Eqs. 1-3: connect.comp's continuityOfDot); ∞ across components.
template <int N>
TLAB_INLINE typename Lanes<N>::F continuity(const Predicting<N>& i, typename Lanes<N>::F jz, typename Lanes<N>::I jComp,
                                            typename Lanes<N>::F normalDot, const Weights& w) {
  using V = Lanes<N>;
  const auto epsZ = V::absolute(i.predicted - jz) / w.r;  // Eq. 1
  const auto epsN = 1.0f - normalDot;                     // Eq. 2
  const auto e = w.wz * epsZ + w.wn * epsN;               // Eq. 3
  return i.comp != jComp ? V::splat(kInfinity) : e;
}

// connect.comp's beyond: a depth gap past which no fragment matches better than bestEps.
template <int N>
TLAB_INLINE typename Lanes<N>::I beyond(typename Lanes<N>::F depthGap, typename Lanes<N>::F bestEps, const Weights& w) {
  return w.gapScale * depthGap - w.wnSlack > bestEps + Lanes<N>::absolute(bestEps) * 1e-5f;
}

// connect.comp's fastNeighbor for layer L of N lists towards their adjacent lists: `same` where it
// answers the same layer of the adjacent list, `unresolved` where it answers UNRESOLVED (else
// NO_NEIGHBOR). Lanes beyond a list's end hold any values: the masks leave them out, as the
// shader's conditions do.
template <int N>
struct Answer {
  typename Lanes<N>::I same, unresolved;
};
template <int N>
struct FastQuery {
  using F = typename Lanes<N>::F;
  using I = typename Lanes<N>::I;
  Predicting<N> a, prev, next;  // layer L of the own lists and the layers next to it
  I n, countB;                  // the own and the adjacent lists' lengths
  F bz, bPrevZ, bNextZ;
  I bComp;
  F maxStep;
  F dotCur, dotNext, dotPrev;  // n_a·n_b, n_next·n_b, n_prev·n_b
};
template <int N>
TLAB_INLINE Answer<N> fastNeighbor(const FastQuery<N>& q, std::int32_t L, const Weights& w) {
  using V = Lanes<N>;
  using I = typename V::I;
  const auto predicted = q.a.predicted;
  const auto e = continuity<N>(q.a, q.bz, q.bComp, q.dotCur, w);
  I unresolved = (L >= q.countB) | ~(e < kInfinity) |
                 ((L + 1 < q.countB) & ~((q.bNextZ >= predicted) & beyond<N>(q.bNextZ - predicted, e, w)));
  if (L > 0) unresolved |= ~((q.bPrevZ <= predicted) & beyond<N>(predicted - q.bPrevZ, e, w));
  // The mutual test over the own list (Alg. 2's second half).
  const I hasNext = L + 1 < q.n;
  const I nextFar = ~hasNext | (q.next.z >= q.bz);
  const I nextVisited = hasNext & ~beyond<N>(nextFar ? q.next.z - q.bz - q.maxStep : q.bz - q.next.z - q.maxStep, e, w);
  I prevFar = V::all(), prevVisited = I{};
  if (L > 0) {
    prevFar = q.prev.z <= q.bz;
    prevVisited = ~beyond<N>(prevFar ? q.bz - q.prev.z - q.maxStep : q.prev.z - q.bz - q.maxStep, e, w);
  }
  const I beaten = (nextVisited & (continuity<N>(q.next, q.bz, q.bComp, q.dotNext, w) < e)) |
                   (prevVisited & (continuity<N>(q.prev, q.bz, q.bComp, q.dotPrev, w) < e));
  const I forwardDone = (L + 2 >= q.n) | (nextFar & ~nextVisited);
  const I backwardDone = L < 2 ? V::all() : prevFar & ~prevVisited;
  const I hasList = q.countB != 0;  // no list (also beyond the image edge): no neighbour
  const I done = forwardDone & backwardDone;
  return {hasList & ~unresolved & ~beaten & done, hasList & (unresolved | (~beaten & ~done))};
}

template <int N>
TLAB_INLINE typename Lanes<N>::F dot(const typename Lanes<N>::F a[3], const typename Lanes<N>::F b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Settles the pairs of row y (A) with the pixels to their right (same row) and above (row y + 1).
struct RowPass {
  const CoveredGrid& grid;
  const Weights& w;
  FastLinks& out;
  FastLinkRows& work;
  bool& partial;
  int rowsFrom, rowsTo;  // this thread's rows

  template <int N>
  TLAB_INLINE void run(const RowPlanes& a, const RowPlanes& up, int y) const {
    for (int x0 = a.first; x0 <= a.last; x0 += N) chunk<N>(a, up, y, x0);
  }

  template <int N>
  TLAB_INLINE void chunk(const RowPlanes& a, const RowPlanes& up, int y, int x0) const {
    using V = Lanes<N>;
    using F = typename V::F;
    using I = typename V::I;
    const I nA = V::load(a.counts() + x0), nB[2] = {V::load(a.counts() + x0 + 1), V::load(up.counts() + x0)};
    std::int32_t layers = 0;
    for (int j = 0; j < N; ++j)
      if (nA[j] > 0) layers = std::max({layers, nA[j], nB[0][j], nB[1][j]});
    if (layers == 0) return;
    const I active = nA > 0;
    const F stepA[2] = {V::load(a.stepX() + x0), V::load(a.stepY() + x0)};
    const F stepB[2] = {V::load(a.stepX() + x0 + 1), V::load(up.stepY() + x0)};
    const I headA = V::load(a.heads() + x0), headB[2] = {V::load(a.heads() + x0 + 1), V::load(up.heads() + x0)};
    const RowPlanes* rowB[2] = {&a, &up};
    const int xB[2] = {x0 + 1, x0};
    // What the step settles, lane by lane: the link words of each layer both ways,
    // words[((2 × pair + side) × layers + L) × N + lane] (side 0: A's, 1: B's); per pair, whether
    // it is listed, and (with pair bits) the layers A links to the same layer.
    if (work.words.size() < std::size_t(4 * layers * N)) work.words.resize(std::size_t(4 * layers * N));
    std::int32_t* words = work.words.data();
    I listedPair[2] = {I{}, I{}}, sameA[2] = {I{}, I{}};
    // NO_NEIGHBOR and UNRESOLVED as int32 lanes; with pair bits, a listed pair's words are its kept
    // links or UNRESOLVED (both ways: phase 3 searches the rest).
    const I none = V::all(), unresolved = none - 1;
    const bool bits = out.pairs != nullptr;
    for (int i = 0; i < 2; ++i) {
      // The normals' products carried to the next layer (connect.comp's aNextDotB, bNextDotA).
      F aNextDotB{}, bNextDotA{};
      for (std::int32_t L = 0; L < layers; ++L) {
        const std::uint32_t l = std::uint32_t(L), prevL = L > 0 ? l - 1 : 0u;
        const Surfels<N> aCur = surfelsAt<N>(a, l, x0), aNext = surfelsAt<N>(a, l + 1, x0), aPrev = surfelsAt<N>(a, prevL, x0);
        const Surfels<N> bCur = surfelsAt<N>(*rowB[i], l, xB[i]), bNext = surfelsAt<N>(*rowB[i], l + 1, xB[i]),
                         bPrev = surfelsAt<N>(*rowB[i], prevL, xB[i]);
        const F aPrevDotB = bNextDotA, bPrevDotA = aNextDotB;
        const F curDot = dot<N>(aCur.n, bCur.n);
        aNextDotB = dot<N>(aNext.n, bCur.n);
        bNextDotA = dot<N>(bNext.n, aCur.n);
        const FastQuery<N> forA{towards(aCur, i, false), towards(aPrev, i, false), towards(aNext, i, false), nA, nB[i],
                                bCur.z, bPrev.z, bNext.z, bCur.comp, stepA[i], curDot, aNextDotB, aPrevDotB};
        const FastQuery<N> forB{towards(bCur, i, true), towards(bPrev, i, true), towards(bNext, i, true), nB[i], nA,
                                aCur.z, aPrev.z, aNext.z, aCur.comp, stepB[i], curDot, bNextDotA, bPrevDotA};
        const Answer<N> fa = fastNeighbor<N>(forA, L, w), fb = fastNeighbor<N>(forB, L, w);
        const I hasA = (L < nA) & active, hasB = (L < nB[i]) & active;
        const I aSame = hasA & fa.same, aOpen = hasA & fa.unresolved, bSame = hasB & fb.same, bOpen = hasB & fb.unresolved;
        // connect.comp's settledLink: a chosen link is kept unless the other end chose nobody.
        const I keepA = aSame & (bSame | bOpen), keepB = bSame & (aSame | aOpen);
        listedPair[i] |= aOpen | bOpen;
        const I missingA = bits ? unresolved : aOpen ? unresolved : none, missingB = bits ? unresolved : bOpen ? unresolved : none;
        const I wordA = keepA ? headB[i] + L : missingA, wordB = keepB ? headA + L : missingB;
        V::store(words + ((2 * i) * layers + L) * N, wordA);
        V::store(words + ((2 * i + 1) * layers + L) * N, wordB);
        if (bits) sameA[i] |= keepA & std::int32_t(1u << (l & 31u));  // lists of at most 32 layers
        // As words, the links up are the next row's links down: it takes them from here.
        if (!bits && i == 1) V::store(work.belowWords[(y + 1) & 1].data() + std::size_t(L) * a.pitch() + x0, wordB);
      }
    }
    for (int j = 0; j < N; ++j) {
      if (nA[j] <= 0) continue;
      const std::array<std::uint32_t, 2> countB{std::uint32_t(nB[0][j]), std::uint32_t(nB[1][j])},
          headsB{std::uint32_t(headB[0][j]), std::uint32_t(headB[1][j])};
      const std::array<bool, 2> listed{listedPair[0][j] != 0, listedPair[1][j] != 0};
      if (bits) {
        settlePairsPixel(x0 + j, y, std::uint32_t(nA[j]), std::uint32_t(headA[j]), countB, headsB, listed,
                         {std::uint32_t(sameA[0][j]), std::uint32_t(sameA[1][j])}, words + j, layers, N);
        continue;
      }
      // The links left: B's words of the pair with the pixel to the left, in this step's lane before
      // or the last lane of the step before (carried).
      const bool carried = j == 0;
      settleWordsPixel(a, x0 + j, y, std::uint32_t(nA[j]), std::uint32_t(headA[j]), countB[1], headsB[1], listed,
                       words + j, layers, N, carried ? work.carry.data() : words + layers * N + j - 1, carried ? 1 : N);
    }
    if (!bits) {  // the last lane's links left for the next step's first pixel
      if (work.carry.size() < std::size_t(layers)) work.carry.resize(std::size_t(layers));
      for (std::int32_t L = 0; L < layers; ++L) work.carry[std::size_t(L)] = words[(layers + L) * N + N - 1];
    }
  }

  // One pixel's links as words (each fragment's four in one store), from the words its step
  // settled (words[((2 × pair + side) × layers + L) × stride]), the links left (left[L × leftStride])
  // and the links down (the row below's step stored them; at the first of this thread's rows another
  // thread writes them); at the last of its rows the next row's links down. With the work list, and
  // phase 2 folded in (FastLinks::conditions) where none of the pixel's pairs was listed.
  void settleWordsPixel(const RowPlanes& a, int x, int y, std::uint32_t n, std::uint32_t head, std::uint32_t countAbove,
                        std::uint32_t headAbove, const std::array<bool, 2>& listed, const std::int32_t* words, std::int32_t layers,
                        int stride, const std::int32_t* left, int leftStride) const {
    const std::uint32_t pixel = grid.indexAt({x, y});
    const std::int32_t *right = words, *above = words + 2 * layers * stride;
    const std::int32_t* below = work.belowWords[y & 1].data() + x;
    const std::size_t belowStride = a.pitch();
    const bool leftEmpty = x == 0 || a.counts()[x - 1] == 0, belowEmpty = y == 0 || grid.counts[pixel - std::uint32_t(grid.width)] == 0;
    const bool firstRow = y == rowsFrom && y > 0;  // the links down are another thread's to write
    for (int i = 0; i < 2; ++i)
      if (listed[i]) work.listed.push_back(2 * pixel + std::uint32_t(i));
    // Phase 2 here where none of the pixel's pairs was listed (then all its links are final).
    bool fold = false;
    if (out.conditions) {
      std::uint8_t* row = work.listedPairs[y & 1].data();
      row[x] = std::uint8_t((listed[0] ? 1 : 0) | (listed[1] ? 2 : 0));
      fold = row[x] == 0 && (x == 0 || (row[x - 1] & 1) == 0) &&
             (y == 0 || (!firstRow && (work.listedPairs[(y + 1) & 1][std::size_t(x)] & 2) == 0));
      if (!fold) work.deferred.push_back(pixel);
    }
    const std::uint32_t outside = std::uint32_t(x == 0) + std::uint32_t(x == grid.width - 1) + std::uint32_t(y == 0) +
                                  std::uint32_t(y == grid.height - 1);
    for (std::uint32_t l = 0; l < n; ++l) {
      const glm::uvec4 link(leftEmpty ? kNone : std::uint32_t(left[l * leftStride]), std::uint32_t(right[l * stride]),
                            belowEmpty ? kNone : std::uint32_t(below[l * belowStride]), std::uint32_t(above[l * stride]));
      if (!firstRow || belowEmpty) out.links[head + l] = link;
      else out.links[head + l][0] = link[0], out.links[head + l][1] = link[1], out.links[head + l][3] = link[3];
      if (fold) setSameLayerFragment(*out.conditions, head + l, link, outside, work.seeds);
    }
    if (y + 1 == rowsTo) {  // the next thread's first row takes its links down from here
      const std::int32_t* up = words + 3 * layers * stride;
      for (std::uint32_t l = 0; l < countAbove; ++l) out.links[headAbove + l][2] = std::uint32_t(up[l * stride]);
    }
  }

  // One pixel's links as pair bits (TLAB_LINK_MASKS), from what its step settled
  // (words[((2 × pair + side) × layers + L) × stride]): its pair word, and the listed pairs' words
  // both ways (phase 3 searches them); with the work list and `partial` as connect.comp writes them.
  void settlePairsPixel(int x, int y, std::uint32_t n, std::uint32_t head, const std::array<std::uint32_t, 2>& countB,
                        const std::array<std::uint32_t, 2>& headB, const std::array<bool, 2>& listed,
                        const std::array<std::uint32_t, 2>& sameA, const std::int32_t* words, std::int32_t layers, int stride) const {
    const glm::ivec2 xy(x, y), kPairDirections[2] = {{1, 0}, {0, 1}};
    const std::uint32_t pixel = grid.indexAt(xy);
    for (int i = 0; i < 2; ++i) {
      if (!listed[i]) continue;
      const std::int32_t *fromA = words + (2 * i) * layers * stride, *fromB = words + (2 * i + 1) * layers * stride;
      for (std::uint32_t l = 0; l < n; ++l) out.links[head + l][2 * i + 1] = std::uint32_t(fromA[l * stride]);
      for (std::uint32_t l = 0; l < countB[i]; ++l) out.links[headB[i] + l][2 * i] = std::uint32_t(fromB[l * stride]);
    }
    out.pairs[pixel] = glm::uvec4(sameA[0], sameA[1], (listed[0] ? 1u : 0u) | (listed[1] ? 2u : 0u), 0u);
    // Whether the pixel and its pairs link the same layer all round (connect.comp's `partial`).
    bool whole = !listed[0] && !listed[1];
    for (int i = 0; i < 2 && whole && !partial; ++i) {
      const std::uint32_t all = n >= 32u ? 0xFFFFFFFFu : (1u << n) - 1u;
      whole = whole && (!grid.inside(xy + kPairDirections[i]) || (countB[i] == n && sameA[i] == all));
      whole = whole && (!grid.inside(xy - kPairDirections[i]) || grid.countAt(xy - kPairDirections[i]) > 0u);
    }
    if (!whole) partial = true;
    for (int i = 0; i < 2; ++i)
      if (listed[i]) work.listed.push_back(2 * pixel + std::uint32_t(i));
  }
};

// Row y's sorted records asked into the cache (a hint: no word changes). Every pixel's head is the
// count of the fragments before it (the prefix sum), so the row's records lie one after another
// from its first pixel's head to its last pixel's end. Issued two rows ahead of the row settled, so
// that they arrive while the row before is settled: without it a tenth of phase 1 waited on the
// first record of each pixel. (Asking for the lines phase 1 writes as well gained nothing.)
TLAB_INLINE void prefetchRecords(const CoveredGrid& grid, const SortedSurfels& s, int y) {
  if (y >= grid.height) return;
  const std::size_t first = std::size_t(y) * grid.width, last = first + grid.width - 1;
  const char* begin = reinterpret_cast<const char*>(s.words + std::size_t(grid.heads[first]) * s.stride);
  const char* end = reinterpret_cast<const char*>(s.words + (std::size_t(grid.heads[last]) + grid.counts[last]) * s.stride);
  for (const char* line = begin; line < end; line += 64) __builtin_prefetch(line, 0, 3);
}

// Rows [from, to) of the grid, N lanes at a time; returns `partial` for them.
template <int N>
TLAB_INLINE bool settleRows(const CoveredGrid& grid, const SortedSurfels& surfels, const Weights& w, FastLinks& out,
                            FastLinkRows& work, std::size_t pitch, std::uint32_t layers, std::size_t from, std::size_t to) {
  bool partial = false;
  RowPlanes rows[2] = {RowPlanes(work.rows[0], pitch, layers), RowPlanes(work.rows[1], pitch, layers)};
  int current = 0;
  rows[current].load<N>(grid, surfels, int(from));
  prefetchRecords(grid, surfels, int(from) + 1);
  const RowPass pass{grid, w, out, work, partial, int(from), int(to)};
  for (std::size_t y = from; y < to; ++y) {
    const int next = 1 - current;
    prefetchRecords(grid, surfels, int(y) + 2);
    rows[next].load<N>(grid, surfels, int(y) + 1);
    if (out.conditions) std::fill(work.listedPairs[y & 1].begin(), work.listedPairs[y & 1].end(), 0);
    pass.run<N>(rows[current], rows[next], int(y));
    current = next;
  }
  return partial;
}

bool settleRowsSse(const CoveredGrid& grid, const SortedSurfels& surfels, const Weights& w, FastLinks& out,
                   FastLinkRows& work, std::size_t pitch, std::uint32_t layers, std::size_t from, std::size_t to) {
  return settleRows<4>(grid, surfels, w, out, work, pitch, layers, from, to);
}

using SettleRows = bool (*)(const CoveredGrid&, const SortedSurfels&, const Weights&, FastLinks&, FastLinkRows&, std::size_t,
                            std::uint32_t, std::size_t, std::size_t);

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] bool settleRowsAvx2(const CoveredGrid& grid, const SortedSurfels& surfels, const Weights& w,
                                            FastLinks& out, FastLinkRows& work, std::size_t pitch, std::uint32_t layers,
                                            std::size_t from, std::size_t to) {
  return settleRows<8>(grid, surfels, w, out, work, pitch, layers, from, to);
}
// The widest lanes the CPU runs: 8 with AVX2, else 4. (16 with AVX-512 were tried twice: built
// through a target attribute GCC 12 compiles the inlined templates' 64-byte comparisons one lane at
// a time, 2.5 times slower; with the whole file built for AVX-512 they gained a fifteenth, but such
// a file's copies of shared inline functions may be the ones the linker keeps, and those stop a
// CPU without AVX-512.)
SettleRows widest() { return __builtin_cpu_supports("avx2") ? settleRowsAvx2 : settleRowsSse; }
#else
SettleRows widest() { return settleRowsSse; }
#endif

}  // namespace

void settleFastLinksOnHost(const CoveredGrid& grid, const SortedSurfels& surfels, const ContinuityWeights& weights,
                           FastLinks& out, std::vector<FastLinkRows>& work, unsigned threads, FastLinkLanes lanes) {
  if (out.conditions && out.pairs) throw std::logic_error("connect phase 1 folds phase 2 in only where the links are words");
  out.listed.clear();
  out.partial = false;
  out.deferred.clear();
  if (grid.width <= 0 || grid.height <= 0) return;
  std::uint32_t longest = 0;
  for (std::size_t p = 0, pixels = std::size_t(grid.width) * grid.height; p < pixels; ++p) longest = std::max(longest, grid.counts[p]);
  if (longest == 0) return;
  const Weights w{weights.objectRadius, weights.wz, weights.gapScale, weights.wn, weights.wn * kEpsNSlack};
  // Columns up to the last pixel's right neighbour's and a chunk's lanes beyond; planes up to L + 1.
  const std::size_t pitch = std::size_t(grid.width) + 2 * kMaxLanes;
  const std::uint32_t layers = longest + 1;
  const std::size_t shares = std::clamp<std::size_t>(threads, 1, std::size_t(grid.height));
  if (work.size() < shares) work.resize(shares);
  const SettleRows settle = lanes == FastLinkLanes::Widest ? widest() : settleRowsSse;
  std::vector<char> partial(shares, 0);
  core::forEachShare(std::size_t(grid.height), shares, [&](std::size_t from, std::size_t to, std::size_t share) {
    FastLinkRows& mine = work[share];
    mine.listed.clear();
    mine.deferred.clear();
    mine.seeds.beta.clear();
    mine.seeds.gamma.clear();
    for (auto& row : mine.listedPairs) row.resize(pitch);
    if (!out.pairs)
      for (auto& plane : mine.belowWords)
        if (plane.size() < layers * pitch) plane.resize(layers * pitch);
    partial[share] = settle(grid, surfels, w, out, mine, pitch, layers, from, to);
  });
  const auto append = [](std::vector<std::uint32_t>* to, const std::vector<std::uint32_t>& from) {
    if (to) to->insert(to->end(), from.begin(), from.end());
  };
  for (std::size_t s = 0; s < shares; ++s) {  // the shares in row order
    append(&out.listed, work[s].listed);
    out.partial = out.partial || partial[s] != 0;
    if (!out.conditions) continue;
    append(&out.deferred, work[s].deferred);
    append(out.conditions->betaSeeds, work[s].seeds.beta);
    append(out.conditions->gammaSeeds, work[s].seeds.gamma);
  }
}

}  // namespace tlab::render
