// The connect pass's phase 2 as host code (ops/boundary_conditions.hpp, issue #29) on hand-made
// links whose boundary conditions (Carnecky Sec. 5.3) are worked out below; the GL suite compares it
// with the shader (NeighborLinks.PhaseTwoAsHostCodeLeavesTheShadersFields).
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "renderer/ops/boundary_conditions.hpp"

using namespace tlab::render;

namespace {
constexpr std::uint32_t kNone = 0xFFFFFFFFu;
}

// A 3 × 1 image: pixel 0 holds fragments 0 (front) and 1, pixel 1 fragment 2, pixel 2 fragment 3.
// Fragment 0 has no neighbour within the image: a silhouette (β = 1, a seed; β fixed). Fragment 1
// links to 2, the front layer of the next list: it lies right under a silhouette (β = 0, fixed).
// Fragment 2 links back to a layer behind its own: beside an occluding edge (γ = 1, a seed; γ
// fixed). Fragment 3 links to 2, and the image edge is no silhouette: all free.
TEST(BoundaryConditionsOnHost, SilhouettesHalosAndTheImageEdge) {
  const std::vector<std::uint32_t> counts{2, 1, 1}, heads{0, 2, 3}, covered{0, 1, 2};
  std::vector<glm::uvec4> links{{kNone, kNone, kNone, kNone}, {kNone, 2, kNone, kNone}, {1, 3, kNone, kNone}, {2, kNone, kNone, kNone}};
  std::vector<std::uint32_t> flags(4, 0xDEAD), betaSeeds, gammaSeeds;
  std::vector<float> beta(4, -1.0f), gamma(4, -1.0f);
  setBoundaryConditionsOnHost({3, 1, counts.data(), heads.data(), covered.data(), covered.size()},
                              {links.data(), nullptr, flags.data(), beta.data(), gamma.data(), &betaSeeds, &gammaSeeds});
  EXPECT_EQ(flags, (std::vector<std::uint32_t>{1 | 4, 1 | 4, 1 | 2, 1 | 2 | 4}));
  EXPECT_EQ(beta, (std::vector<float>{1, 0, 0, 0}));
  EXPECT_EQ(gamma, (std::vector<float>{0, 0, 1, 0}));
  EXPECT_EQ(betaSeeds, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(gammaSeeds, (std::vector<std::uint32_t>{2}));
}

// Links kept as pair bits: a 2 × 2 image of one fragment a pixel. Pixel 0's pair word links layer 0
// to the right and up; pixel 1's up; pixel 2's to the right. The words phase 1 left are not read
// (no pair listed) but overwritten with the links of the bits; pixel 0's pair up is listed instead
// in a second run, and then its words are the links.
TEST(BoundaryConditionsOnHost, LinksFromPairBitsOrTheListedPairsWords) {
  const std::vector<std::uint32_t> counts{1, 1, 1, 1}, heads{0, 1, 2, 3}, covered{0, 1, 2, 3};
  std::vector<glm::uvec4> pairs{{1, 1, 0, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 0}};
  std::vector<glm::uvec4> links(4, glm::uvec4(7u));
  std::vector<std::uint32_t> flags(4);
  const CoveredGrid grid{2, 2, counts.data(), heads.data(), covered.data(), covered.size()};
  setBoundaryConditionsOnHost(grid, {links.data(), pairs.data(), flags.data()});
  const std::vector<glm::uvec4> expected{{kNone, 1, kNone, 2}, {0, kNone, kNone, 3}, {kNone, 3, 0, kNone}, {2, kNone, 1, kNone}};
  EXPECT_EQ(links, expected);
  EXPECT_EQ(flags, (std::vector<std::uint32_t>(4, 7))) << "each fragment has its neighbours within the image";
  pairs[0].z = 2;  // pixel 0's pair up listed: fragments 0 and 2 take their words for it
  std::vector<glm::uvec4> words(4, glm::uvec4(kNone));
  words[0][3] = kNone;  // the full search found no link up from fragment 0 ...
  words[2][2] = kNone;  // ... nor down from fragment 2
  setBoundaryConditionsOnHost(grid, {words.data(), pairs.data(), flags.data()});
  EXPECT_EQ(words[0], glm::uvec4(kNone, 1, kNone, kNone));
  EXPECT_EQ(words[2], glm::uvec4(kNone, 3, kNone, kNone));
  EXPECT_EQ(flags, (std::vector<std::uint32_t>{1 | 4, 7, 1 | 4, 7})) << "fragments 0 and 2 lost a neighbour: silhouettes";
}

// A 300 × 200 image of lists of 1 to 3 fragments, each linked to the same layer where the adjacent
// list is as long: one thread and four write the same words and list the same seeds in the same
// (pixel and layer) order.
TEST(BoundaryConditionsOnHost, ManyThreadsWriteTheWordsOfOne) {
  const int w = 300, h = 200;
  std::vector<std::uint32_t> counts, heads, covered;
  std::uint32_t state = 99, head = 0;
  for (std::uint32_t p = 0; p < std::uint32_t(w * h); ++p) {
    state = state * 1664525u + 1013904223u;
    counts.push_back((state >> 16) % 4);  // 0 to 3
    heads.push_back(head);
    head += counts.back();
    if (counts.back() > 0) covered.push_back(p);
  }
  std::vector<glm::uvec4> links(head, glm::uvec4(kNone));
  for (std::uint32_t p = 0; p < counts.size(); ++p) {
    const int x = int(p) % w, y = int(p) / w;
    const int qs[4] = {x > 0 ? int(p) - 1 : -1, x + 1 < w ? int(p) + 1 : -1, y > 0 ? int(p) - w : -1, y + 1 < h ? int(p) + w : -1};
    for (std::uint32_t layer = 0; layer < counts[p]; ++layer)
      for (int k = 0; k < 4; ++k)
        if (qs[k] >= 0 && counts[std::size_t(qs[k])] > layer) links[heads[p] + layer][k] = heads[std::size_t(qs[k])] + (counts[std::size_t(qs[k])] - 1 - layer);
  }
  const CoveredGrid grid{w, h, counts.data(), heads.data(), covered.data(), covered.size()};
  std::vector<std::uint32_t> flags[2], betaSeeds[2], gammaSeeds[2];
  for (int run = 0; run < 2; ++run) {
    flags[run].assign(head, 0);
    setBoundaryConditionsOnHost(grid, {links.data(), nullptr, flags[run].data(), nullptr, nullptr, &betaSeeds[run], &gammaSeeds[run]},
                                run == 0 ? 1 : 4);
  }
  EXPECT_EQ(flags[0], flags[1]);
  EXPECT_EQ(betaSeeds[0], betaSeeds[1]);
  EXPECT_EQ(gammaSeeds[0], gammaSeeds[1]);
  EXPECT_GT(betaSeeds[0].size(), 1000u);
  EXPECT_GT(gammaSeeds[0].size(), 1000u);
  EXPECT_TRUE(std::is_sorted(betaSeeds[0].begin(), betaSeeds[0].end()));
}
