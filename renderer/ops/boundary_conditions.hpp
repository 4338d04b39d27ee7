#pragma once
// The connect pass's phase 2 (ops/connect.comp, TLAB_PHASE 2) as host code, for where the GL runs
// on the CPU (issue #29): from each fragment's (mutual) links, the boundary conditions of Carnecky
// Sec. 5.3 on β and γ and their b flags, and Eq. 9's seeds listed for the solve's frontier. The
// words are the shader's (the seeds in pixel and layer order, where the shader's atomics list them
// in any order; no reader depends on it). Eq. 5's adaptive α is left to the shader (its pow).
// No GL here: the connect pass hands in its mapped buffers (ops/connect_pass.cpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/ops/covered_grid.hpp"

namespace tlab::render {

struct BoundaryConditions {
  // Each fragment's 4 links (left, right, below, above; NO_NEIGHBOR 0xFFFFFFFF where none): read,
  // and where `pairs` is given, written from its bits first (TLAB_LINK_MASKS).
  glm::uvec4* links = nullptr;
  // Per pixel: bits of the layers linked to the same layer right (.x) and above (.y), and .z bit i
  // where pair i was listed for phase 3 (its links then are the words). Null: the links are words.
  const glm::uvec4* pairs = nullptr;
  std::uint32_t* flags = nullptr;  // written: FREE_ALPHA | FREE_BETA | FREE_GAMMA less those fixed
  // β and γ at each fragment (1 at a seed, else 0), written where given.
  float* beta = nullptr;
  float* gamma = nullptr;
  // The fragments where β (γ) starts above 0, appended where given.
  std::vector<std::uint32_t>* betaSeeds = nullptr;
  std::vector<std::uint32_t>* gammaSeeds = nullptr;
};

// Seeds listed by one thread, in pixel and layer order.
struct SeedLists {
  std::vector<std::uint32_t> beta, gamma;
};

// Fragment f's boundary conditions where each of its links (`link`: left, right, below, above)
// joins the same layer of the adjacent list or nothing, `outside` of its four neighbours lying
// beyond the image edge: no fragment there is beside or under a silhouette, so γ is 0 and β 1 only
// where a link is missing (Sec. 5.3; the image edge is no silhouette). Connect phase 1 as host code
// calls it for each fragment of a pixel none of whose pairs was listed (ops/fast_links.hpp).
inline void setSameLayerFragment(const BoundaryConditions& out, std::uint32_t f, const glm::uvec4& link, std::uint32_t outside,
                                 SeedLists& seeds) {
  constexpr std::uint32_t kNoNeighbor = 0xFFFFFFFFu, kFreeAlpha = 1, kFreeBeta = 2, kFreeGamma = 4;
  const std::uint32_t found = std::uint32_t(link.x != kNoNeighbor) + std::uint32_t(link.y != kNoNeighbor) +
                              std::uint32_t(link.z != kNoNeighbor) + std::uint32_t(link.w != kNoNeighbor);
  const bool boundary = found + outside < 4u;
  if (out.beta) out.beta[f] = boundary ? 1.0f : 0.0f;
  if (out.gamma) out.gamma[f] = 0.0f;
  if (out.betaSeeds && boundary) seeds.beta.push_back(f);
  out.flags[f] = boundary ? kFreeAlpha | kFreeGamma : kFreeAlpha | kFreeBeta | kFreeGamma;
}

// Every covered pixel's fragments, the pixels shared out among up to `threads` threads (fewer where
// there are few pixels); the seeds are listed in pixel and layer order however many there are.
void setBoundaryConditionsOnHost(const CoveredGrid& grid, const BoundaryConditions& out, unsigned threads = 1);

}  // namespace tlab::render
