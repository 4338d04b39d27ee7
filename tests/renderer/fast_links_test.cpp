// The connect pass's phase 1 as host code (ops/fast_links.hpp, issue #29) on hand-made lists whose
// fast-path answers (Carnecky Alg. 2, Eqs. 1-3) are worked out below, with 8 lanes (where the CPU
// has AVX2) and 4 alike; the GL suite compares it with the shader on rendered scenes
// (NeighborLinks.PhaseOneAsHostCodeWritesTheShadersWords).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <utility>
#include <vector>

#include "renderer/ops/fast_links.hpp"

using namespace tlab::render;

namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu, kUnresolved = 0xFFFFFFFEu;

struct Fragment {
  float z;
  std::uint32_t component = 0;
};

// A row of pixels, each a list sorted front to back: records of depth, triangle, normal (facing
// the viewer: octahedral word 0), ∇z (0) and ids (component in bits 16-30).
struct Lists {
  explicit Lists(std::vector<std::vector<Fragment>> pixels) {
    for (const auto& list : pixels) {
      heads.push_back(std::uint32_t(counts.empty() ? 0 : heads.back() + counts.back()));
      counts.push_back(std::uint32_t(list.size()));
      for (const Fragment& f : list) words.insert(words.end(), {std::bit_cast<std::uint32_t>(f.z), 0u, 0u, 0u, 0u, f.component << 16});
    }
    steps.assign(counts.size(), glm::vec2(0.0f));
  }
  std::vector<std::uint32_t> counts, heads, words;
  std::vector<glm::vec2> steps;
};

// r_obj, wz, wz / r_obj and wn all 1.
constexpr ContinuityWeights kUnitWeights{1.0f, 1.0f, 1.0f, 1.0f};

// Phase 1 over the lists as one row (r_obj = wz = wn = 1), with the links as words, or as pair bits.
struct Settled {
  std::vector<glm::uvec4> links, pairs;
  std::vector<std::uint32_t> listed;
  bool partial = false;
};
Settled settle(const Lists& lists, bool pairBits, FastLinkLanes lanes) {
  Settled s;
  s.links.assign(lists.words.size() / 6, glm::uvec4(0xDEAD));
  if (pairBits) s.pairs.assign(lists.counts.size(), glm::uvec4(0xDEAD));
  const CoveredGrid grid{int(lists.counts.size()), 1, lists.counts.data(), lists.heads.data(), nullptr, 0};
  const SortedSurfels surfels{lists.words.data(), 6, 3, 2, true, 5, lists.steps.data()};
  FastLinks out;
  out.links = s.links.data();
  out.pairs = pairBits ? s.pairs.data() : nullptr;
  std::vector<FastLinkRows> work;
  settleFastLinksOnHost(grid, surfels, kUnitWeights, out, work, 1, lanes);
  s.listed = out.listed;
  s.partial = out.partial;
  return s;
}

}  // namespace

// Two lists of the same two parallel layers: each layer links to the same layer of the other list,
// and to nothing beyond the image edge; no pair is left for the full search.
TEST(FastLinksOnHost, ParallelLayersLinkLayerToLayer) {
  const Lists lists({{{1.0f}, {2.0f}}, {{1.0f}, {2.0f}}});
  for (FastLinkLanes lanes : {FastLinkLanes::Widest, FastLinkLanes::Four}) {
    const Settled words = settle(lists, false, lanes);
    EXPECT_EQ(words.links, (std::vector<glm::uvec4>{{kNone, 2, kNone, kNone}, {kNone, 3, kNone, kNone},
                                                    {0, kNone, kNone, kNone}, {1, kNone, kNone, kNone}}));
    EXPECT_TRUE(words.listed.empty());
    // As pair bits: pixel 0 links both layers to the right; nothing else, and no word written.
    const Settled bits = settle(lists, true, lanes);
    EXPECT_EQ(bits.pairs, (std::vector<glm::uvec4>{{3, 0, 0, 0}, {0, 0, 0, 0}}));
    EXPECT_EQ(bits.links, std::vector<glm::uvec4>(4, glm::uvec4(0xDEAD)));
    EXPECT_FALSE(bits.partial);  // linked all round, the rest being the image edge
  }
}

// Layer 1 of the first list has no same layer in the next list: the fast path cannot say and lists
// the pair (its links as words, layer 0's kept: the back layer lies beyond ε of the front match).
TEST(FastLinksOnHost, AListLongerThanItsNeighbourIsLeftToTheFullSearch) {
  const Lists lists({{{1.0f}, {2.0f}}, {{1.0f}}});
  for (FastLinkLanes lanes : {FastLinkLanes::Widest, FastLinkLanes::Four}) {
    const Settled words = settle(lists, false, lanes);
    EXPECT_EQ(words.links, (std::vector<glm::uvec4>{{kNone, 2, kNone, kNone}, {kNone, kUnresolved, kNone, kNone},
                                                    {0, kNone, kNone, kNone}}));
    EXPECT_EQ(words.listed, (std::vector<std::uint32_t>{0}));  // 2 × pixel 0 + axis 0 (to the right)
    const Settled bits = settle(lists, true, lanes);
    EXPECT_EQ(bits.pairs[0], glm::uvec4(1, 0, 1, 0));  // layer 0 linked; pair 0 listed
    EXPECT_EQ(bits.links[0][1], 2u);                    // the listed pair's words, both ways
    EXPECT_EQ(bits.links[1][1], kUnresolved);
    EXPECT_EQ(bits.links[2][0], 0u);
    EXPECT_TRUE(bits.partial);
  }
}

// Alg. 2's mutual test: the front layer at depth 1.0 would choose the neighbour's only fragment at
// 1.06, but the own list's layer at 1.05 matches that fragment better (ε 0.01 against 0.06): no
// link for the front layer; the second layer has no same layer next door (listed).
TEST(FastLinksOnHost, ABetterMatchInTheOwnListTakesTheLinkAway) {
  const Lists lists({{{1.0f}, {1.05f}}, {{1.06f}}});
  for (FastLinkLanes lanes : {FastLinkLanes::Widest, FastLinkLanes::Four}) {
    const Settled words = settle(lists, false, lanes);
    EXPECT_EQ(words.links[0][1], kNone);
    EXPECT_EQ(words.links[1][1], kUnresolved);
    EXPECT_EQ(words.listed, (std::vector<std::uint32_t>{0}));
  }
}

// Fragments of different connected components are never neighbours (ε = ∞): the fast path leaves
// them to the full search. Nine pixels in a row fill more than one step of lanes; only the pair
// across the component change is listed.
TEST(FastLinksOnHost, AnotherComponentIsNoNeighbourAndLanesCarryOn) {
  std::vector<std::vector<Fragment>> pixels(9, std::vector<Fragment>{{1.0f, 1}});
  pixels[6][0].component = 2;
  const Lists lists(pixels);
  for (FastLinkLanes lanes : {FastLinkLanes::Widest, FastLinkLanes::Four}) {
    const Settled words = settle(lists, false, lanes);
    EXPECT_EQ(words.listed, (std::vector<std::uint32_t>{2 * 5, 2 * 6}));
    for (std::uint32_t p = 0; p < 9; ++p) {
      const std::uint32_t right = p == 8 ? kNone : p == 5 || p == 6 ? kUnresolved : p + 1;
      const std::uint32_t left = p == 0 ? kNone : p == 6 || p == 7 ? kUnresolved : p - 1;
      EXPECT_EQ(words.links[p], glm::uvec4(left, right, kNone, kNone)) << p;
    }
  }
}

namespace {

// A width × height image of patches of lists of 1 to 4 layers at depths 1, 2, 3, 4 (each patch's
// shifted by its own few hundredths), some pixels empty and now and then a layer of another
// component: pairs the fast path settles, and pairs it lists (across patches, other components).
struct Image {
  Image(int width, int height) : w(width), h(height) {
    std::uint32_t state = 12345u;
    const auto next = [&state] { return state = state * 1664525u + 1013904223u; };  // (Numerical Recipes' LCG)
    for (int p = 0; p < w * h; ++p) {
      const int patch = p % w / 12 + p / w / 8;
      const std::uint32_t n = (p % w + 3 * (p / w)) % 17 == 0 ? 0u : 1u + std::uint32_t(patch % 4), shift = std::uint32_t(patch % 3);
      heads.push_back(std::uint32_t(words.size() / 6));
      counts.push_back(n);
      for (std::uint32_t l = 0; l < n; ++l) {
        const std::uint32_t component = (next() >> 8) % 211u == 0 ? 1u : 0u;
        words.insert(words.end(), {std::bit_cast<std::uint32_t>(1.0f + float(l) + 0.02f * float(shift)), 0u, 0u, 0u, 0u, component << 16});
      }
      if (n > 0) covered.push_back(std::uint32_t(p));
    }
    steps.assign(counts.size(), glm::vec2(0.0f));
  }
  CoveredGrid grid() const { return {w, h, counts.data(), heads.data(), covered.data(), covered.size()}; }
  // Records of 6 words: depth, ∇z at 3, the normal at 2, the ids at 5.
  SortedSurfels surfels() const { return {words.data(), 6, 3, 2, true, 5, steps.data()}; }
  std::size_t fragments() const { return words.size() / 6; }
  int w, h;
  std::vector<std::uint32_t> counts, heads, covered, words;
  std::vector<glm::vec2> steps;
};

// What phase 2 leaves, with phase 1 before it (the links as words).
struct Conditions {
  std::vector<glm::uvec4> links;
  std::vector<std::uint32_t> flags, betaSeeds, gammaSeeds;
  std::vector<float> beta, gamma;
  std::size_t deferred = 0;
  explicit Conditions(const Image& image)
      : links(image.fragments(), glm::uvec4(0xDEAD)), flags(image.fragments(), 0xDEAD), beta(image.fragments(), -1.0f),
        gamma(image.fragments(), -1.0f) {}
  BoundaryConditions outputs(std::vector<std::uint32_t>* betaList, std::vector<std::uint32_t>* gammaList) {
    return {links.data(), nullptr, flags.data(), beta.data(), gamma.data(), betaList, gammaList};
  }
};

// Phase 1, then phase 2 over every covered pixel (`fold` false); or phase 2 folded into phase 1 and
// then over the pixels it deferred, the seeds merged (as ops/connect_pass.cpp does).
Conditions phasesOneAndTwo(const Image& image, bool fold, unsigned threads) {
  Conditions c(image);
  FastLinks out;
  out.links = c.links.data();
  if (fold) out.conditions = c.outputs(&c.betaSeeds, &c.gammaSeeds);
  std::vector<FastLinkRows> work;
  settleFastLinksOnHost(image.grid(), image.surfels(), kUnitWeights, out, work, threads);
  CoveredGrid rest = image.grid();
  if (fold) rest.covered = out.deferred.data(), rest.coveredCount = out.deferred.size();
  std::vector<std::uint32_t> beta, gamma;
  setBoundaryConditionsOnHost(rest, c.outputs(&beta, &gamma), threads);
  for (auto [seeds, more] : {std::pair{&c.betaSeeds, &beta}, std::pair{&c.gammaSeeds, &gamma}}) {
    const std::size_t folded = seeds->size();
    seeds->insert(seeds->end(), more->begin(), more->end());
    std::inplace_merge(seeds->begin(), seeds->begin() + std::ptrdiff_t(folded), seeds->end());
  }
  c.deferred = out.deferred.size();
  return c;
}

}  // namespace

// Phase 2 folded into phase 1 (FastLinks::conditions, links as words) leaves what phase 2 run
// afterwards leaves: links, flags, β and γ, and the seeds in pixel and layer order, with one thread
// or rows shared among several (whose first rows are deferred, and whose links down the thread
// below writes); pixels beside a listed pair are deferred (as the γ of their unresolved links
// shows), the rest set during phase 1. With pair bits it is refused (the connect pass keeps
// phase 2 apart there).
TEST(FastLinksOnHost, PhaseTwoFoldedInLeavesWhatPhaseTwoAfterwardsLeaves) {
  const Image image(48, 25);
  const Conditions after = phasesOneAndTwo(image, false, 1);
  EXPECT_FALSE(after.gammaSeeds.empty());  // unresolved links (no phase 3 here): next to a "silhouette"
  for (const unsigned threads : {1u, 2u, 3u}) {
    SCOPED_TRACE(threads);
    const Conditions folded = phasesOneAndTwo(image, true, threads);
    EXPECT_EQ(folded.links, after.links);
    EXPECT_EQ(folded.flags, after.flags);
    EXPECT_EQ(folded.beta, after.beta);
    EXPECT_EQ(folded.gamma, after.gamma);
    EXPECT_EQ(folded.betaSeeds, after.betaSeeds);
    EXPECT_EQ(folded.gammaSeeds, after.gammaSeeds);
    EXPECT_GT(folded.deferred, 0u);
    EXPECT_LT(folded.deferred, image.covered.size() / 2);
  }
  Conditions c(image);
  std::vector<glm::uvec4> pairs(image.counts.size());
  FastLinks out;
  out.links = c.links.data();
  out.pairs = pairs.data();
  out.conditions = c.outputs(nullptr, nullptr);
  std::vector<FastLinkRows> work;
  EXPECT_THROW(settleFastLinksOnHost(image.grid(), image.surfels(), kUnitWeights, out, work), std::logic_error);
}
