#include "renderer/ops/boundary_conditions.hpp"

#include <array>

namespace tlab::render {

namespace {

constexpr std::uint32_t kNoNeighbor = 0xFFFFFFFFu;  // NO_NEIGHBOR of ops/field_bindings.glsl
constexpr std::uint32_t kFreeAlpha = 1, kFreeBeta = 2, kFreeGamma = 4;
constexpr std::array<glm::ivec2, 4> kDirections{glm::ivec2(-1, 0), glm::ivec2(1, 0), glm::ivec2(0, -1), glm::ivec2(0, 1)};

// A pixel's pair words and those of the pixels to its left and below (their pairs with it), for
// the links kept as bits (connect.comp's TLAB_LINK_MASKS branch of phase 2).
struct PairsAround {
  glm::uvec4 own{0u}, left{0u}, below{0u};
  bool leftHasList = false, belowHasList = false, anyListed = false;
};

PairsAround pairsAround(const CoveredGrid& g, const glm::uvec4* pairs, std::uint32_t pixel, glm::ivec2 xy) {
  PairsAround p;
  p.own = pairs[pixel];
  const glm::ivec2 leftQ = xy + kDirections[0], belowQ = xy + kDirections[2];
  p.leftHasList = g.countAt(leftQ) > 0u;
  p.belowHasList = g.countAt(belowQ) > 0u;
  if (p.leftHasList) p.left = pairs[g.indexAt(leftQ)];
  if (p.belowHasList) p.below = pairs[g.indexAt(belowQ)];
  p.anyListed = (p.own.z | (p.leftHasList ? p.left.z & 1u : 0u) | (p.belowHasList ? p.below.z & 2u : 0u)) != 0u;
  return p;
}

// Layer `layer`'s links from its pairs' bits, or the words phase 1 (and 3) wrote where a pair was listed.
glm::uvec4 linksFromBits(const PairsAround& p, glm::uvec4 words, std::uint32_t layer, const glm::uvec4& qHead) {
  glm::uvec4 link(kNoNeighbor);
  if (p.anyListed) link = words;
  const std::uint32_t bit = 1u << layer;
  link[1] = (p.own.z & 1u) != 0u ? link[1] : (p.own.x & bit) != 0u ? qHead[1] + layer : kNoNeighbor;
  link[3] = (p.own.z & 2u) != 0u ? link[3] : (p.own.y & bit) != 0u ? qHead[3] + layer : kNoNeighbor;
  link[0] = !p.leftHasList ? kNoNeighbor : (p.left.z & 1u) != 0u ? link[0] : (p.left.x & bit) != 0u ? qHead[0] + layer : kNoNeighbor;
  link[2] = !p.belowHasList ? kNoNeighbor : (p.below.z & 2u) != 0u ? link[2] : (p.below.y & bit) != 0u ? qHead[2] + layer : kNoNeighbor;
  return link;
}

void setPixel(const CoveredGrid& g, const BoundaryConditions& out, std::uint32_t pixel, glm::ivec2 xy, SeedLists& seeds) {
  const std::uint32_t n = g.counts[pixel], head = g.heads[pixel];
  glm::uvec4 qHead(0u);  // heads of the adjacent lists, to turn a link into a layer
  std::uint32_t outside = 0;  // adjacent pixels beyond the image edge
  for (int k = 0; k < 4; ++k) {
    const glm::ivec2 q = xy + kDirections[std::size_t(k)];
    if (g.inside(q)) qHead[k] = g.heads[g.indexAt(q)];
    else ++outside;
  }
  const PairsAround around = out.pairs ? pairsAround(g, out.pairs, pixel, xy) : PairsAround{};
  for (std::uint32_t layer = 0; layer < n; ++layer) {
    const std::uint32_t f = head + layer;
    glm::uvec4 link = out.links[f];
    if (out.pairs) out.links[f] = link = linksFromBits(around, link, layer, qHead);
    std::uint32_t found = 0;
    bool nextToSilhouette = false, underSilhouette = false;
    for (int k = 0; k < 4; ++k) {  // (without branches: whether a link is there is anyone's guess)
      const bool linked = link[k] != kNoNeighbor;
      const std::uint32_t neighborLayer = link[k] - qHead[k];
      found += linked;
      nextToSilhouette |= linked & (layer < neighborLayer);
      underSilhouette |= linked & (layer > neighborLayer);
    }
    // Sec. 5.2 initial conditions, then Sec. 5.3 boundary conditions (as ops/connect.comp).
    float b = 0.0f, gamma = 0.0f;
    std::uint32_t free = kFreeAlpha | kFreeBeta | kFreeGamma;
    if (found + outside < 4u) b = 1.0f, free &= ~kFreeBeta;  // boundary or silhouette; the image edge is no silhouette
    if (nextToSilhouette) gamma = 1.0f, free &= ~kFreeGamma;  // beside an occluding edge
    if (underSilhouette) b = 0.0f, free &= ~kFreeBeta;        // right under a silhouette
    if (out.beta) out.beta[f] = b;
    if (out.gamma) out.gamma[f] = gamma;
    if (out.betaSeeds && b > 0.0f) seeds.beta.push_back(f);
    if (out.gammaSeeds && gamma > 0.0f) seeds.gamma.push_back(f);
    out.flags[f] = free;
  }
}

}  // namespace

void setBoundaryConditionsOnHost(const CoveredGrid& grid, const BoundaryConditions& out, unsigned threads) {
  constexpr std::size_t kPixelsPerShareMin = 16384;
  const std::size_t n = grid.coveredCount, shares = core::sharesFor(n, kPixelsPerShareMin, threads);
  std::vector<SeedLists> seeds(shares);
  forEachCoveredPixel(grid, shares, [&](std::uint32_t pixel, glm::ivec2 xy, std::size_t share) {
    setPixel(grid, out, pixel, xy, seeds[share]);
  });
  for (const SeedLists& s : seeds) {  // the shares in pixel order
    if (out.betaSeeds) out.betaSeeds->insert(out.betaSeeds->end(), s.beta.begin(), s.beta.end());
    if (out.gammaSeeds) out.gammaSeeds->insert(out.gammaSeeds->end(), s.gamma.begin(), s.gamma.end());
  }
}

}  // namespace tlab::render
