#pragma once
// The connect pass's phase 1 (ops/connect.comp, TLAB_PHASE 1) as host code, for where the GL runs
// on the CPU (issue #29): for each pair of adjacent pixels, the fast path of Alg. 2 (Carnecky
// Sec. 4.4) over both lists — ε of Eqs. 1-3 in the shader's single-precision operations and
// order, with no fused multiply-add, as llvmpipe computes them — and the same words: each
// fragment's link words (or, where the pass keeps them so, the pair bits: lists of at most 32
// layers), the pairs left to the full search (phase 3) and the `partial` word. The listed pairs
// come in pixel order, where the shader's atomics list them in any order (phase 3 treats each on
// its own).
//
// Row by row, as lanes: each row's surfels are decoded once into layer planes (plane L holds
// layer L of every pixel of the row), and 8 adjacent pixels (4 without AVX2) are settled at once,
// their pairs to the right read from the same planes one pixel on and those above from the next
// row's. The link words are computed in the lanes too; as words, each fragment's four links are
// gathered (left from the lane before, down from the row below's step) and written in one store,
// and phase 2 can be folded in (FastLinks::conditions). The planes are kept across frames
// (FastLinkRows), as the GL buffers are. No GL here: the connect pass hands in its mapped buffers
// (ops/connect_pass.cpp).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/ops/boundary_conditions.hpp"
#include "renderer/ops/covered_grid.hpp"

namespace tlab::render {

// The sorted records as phase 1 reads them, and each list's maxStep (written by the sort).
struct SortedSurfels {
  const std::uint32_t* words = nullptr;
  std::uint32_t stride = 0;
  std::uint32_t gradientOffset = 0, normalOffset = 0;  // the depth is word 0
  bool hasIds = false;                                 // the component, else 0 for all
  std::uint32_t idsOffset = 0;
  const glm::vec2* steps = nullptr;  // per pixel: max |∂z/∂x|, max |∂z/∂y| over its list
};

// Eqs. 1-3's constants, as the shader's uniforms: r_obj, wz, wz / r_obj (the search's bound), wn.
struct ContinuityWeights {
  float objectRadius = 1.0f, wz = 0.0f, gapScale = 0.0f, wn = 0.0f;
};

// What phase 1 writes.
struct FastLinks {
  // Each fragment's 4 links (left, right, below, above): all of them where `pairs` is null; else
  // only those of the listed pairs (the rest are the pair bits).
  glm::uvec4* links = nullptr;
  // Per covered pixel: bits of the layers linked to the same layer right (.x) and above (.y), and
  // .z bit i where pair i was listed. Null: the links as words (lists of any length).
  glm::uvec4* pairs = nullptr;
  std::vector<std::uint32_t> listed;  // out: 2 × pixel + axis (0: right, 1: above), pixel order
  bool partial = false;               // out: where `pairs` is given, as the shader's word
  // Where given (links as words only: `pairs` null), phase 2 folded in (ops/boundary_conditions.hpp,
  // setSameLayerFragment): each pixel none of whose four pairs was listed (its links are final:
  // phase 3 leaves them alone) gets its boundary conditions from the words just gathered; the
  // others go to `deferred`, for phase 2 after phase 3, as do the first row of each thread's rows
  // (the pairs below it are another thread's). Its links must be `links` above (mapped readable
  // too), and its seeds are appended in pixel and layer order (of the pixels set here).
  std::optional<BoundaryConditions> conditions;
  std::vector<std::uint32_t> deferred;  // out: the pixels left to phase 2, pixel order
};

// One thread's working memory: two rows' layer planes. Kept between frames (resized, never freed).
struct FastLinkRows {
  struct Row {
    std::vector<float> planes;         // 6 planes of layers × padded width: z, ∂z/∂x, ∂z/∂y, n
    std::vector<std::int32_t> comps;   // layers × padded width
    std::vector<std::int32_t> counts;  // padded width (0 beyond the image)
    std::vector<std::int32_t> heads;   // padded width (where the count is above 0)
    std::vector<float> stepX, stepY;   // padded width
    std::uint32_t longest = 0;         // the row's longest list
  };
  Row rows[2];
  std::vector<std::int32_t> words;  // a step's link words per pair, side, layer and lane
  // As words: the last lane's links left for the next step, and per row parity the links down of
  // that row (layers × padded width), stored by the row below's steps.
  std::vector<std::int32_t> carry, belowWords[2];
  std::vector<std::uint32_t> listed;
  // Phase 2 folded in (FastLinks::conditions): per column, bit i where the pixel's pair i was listed,
  // for this row and the one below (by the row's parity); the pixels deferred and seeds listed.
  std::vector<std::uint8_t> listedPairs[2];
  std::vector<std::uint32_t> deferred;
  SeedLists seeds;
};

// How many adjacent pixels a step settles: 8 where the CPU has AVX2, else 4 (SSE); or 4 (tests
// compare the two: the same words).
enum class FastLinkLanes { Widest, Four };

// Every pair of adjacent covered pixels, the rows shared out among up to `threads` threads; `work`
// holds one FastLinkRows a thread (grown as needed, kept by the caller between frames).
void settleFastLinksOnHost(const CoveredGrid& grid, const SortedSurfels& surfels, const ContinuityWeights& weights,
                           FastLinks& out, std::vector<FastLinkRows>& work, unsigned threads = 1,
                           FastLinkLanes lanes = FastLinkLanes::Widest);

}  // namespace tlab::render
