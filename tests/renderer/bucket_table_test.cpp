// The CPU model of the bucketed k-buffer (seed 002, Sec. 4): Z insertion, reorder into buckets,
// the hash table H(b) = b mod k with linear probing, binary search, and the neighbour query
// with buckets against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "renderer/kbuffer/bucket_table.hpp"
#include "renderer/params/transfer_function.hpp"

using namespace tlab::render;
using namespace tlab::render::kbuffer;

namespace {

std::vector<std::uint32_t> emptySlots(std::size_t k) { return std::vector<std::uint32_t>(k, kEmpty); }

}  // namespace

TEST(BucketTable, InsertionKeepsTheKNearestInDepthOrder) {
  auto z = emptySlots(4);
  for (std::uint16_t d : {50, 10, 70, 30, 20, 60}) insertNearest(z, packDepthFirst(d, 1));
  EXPECT_EQ(z, (std::vector<std::uint32_t>{packDepthFirst(10, 1), packDepthFirst(20, 1), packDepthFirst(30, 1),
                                           packDepthFirst(50, 1)}));
}

TEST(BucketTable, FiveShapesGiveFiveBucketsWithTheirRanges) {
  const std::size_t k = 16;
  auto z = emptySlots(k);
  // shape s has s + 1 fragments at depths interleaved with the other shapes
  std::vector<std::pair<std::uint16_t, std::uint16_t>> fragments;  // (depth, shape)
  std::uint16_t depth = 100;
  for (std::uint16_t s = 0; s < 5; ++s)
    for (int i = 0; i <= s; ++i) fragments.push_back({std::uint16_t(depth + 7 * (4 - s) + 40 * i), std::uint16_t(s * 3)});
  for (const auto& [d, s] : fragments) insertNearest(z, packDepthFirst(d, s));
  auto table = emptySlots(k);
  const auto n = buildBuckets(z, table);
  ASSERT_EQ(n, 15u);
  EXPECT_EQ(std::count_if(table.begin(), table.end(), [](auto w) { return w != kEmpty; }), 5);
  std::uint32_t expectedFirst = 0;
  for (std::uint16_t s = 0; s < 5; ++s) {
    const auto b = findBucket(table, std::uint16_t(s * 3));
    ASSERT_TRUE(b) << "shape " << s * 3;
    EXPECT_EQ(b->first, expectedFirst);
    EXPECT_EQ(b->last, expectedFirst + s);
    EXPECT_EQ(*findBucketSlot(table, std::uint16_t(s * 3)), (s * 3u) % k) << "no collision: the slot is H(b)";
    for (std::uint32_t i = b->first; i <= b->last; ++i) EXPECT_EQ(shapeOfShapeFirst(z[i]), s * 3);
    for (std::uint32_t i = b->first; i < b->last; ++i) EXPECT_LT(depthOfShapeFirst(z[i]), depthOfShapeFirst(z[i + 1]));
    expectedFirst += s + 1;
  }
  EXPECT_FALSE(findBucket(table, 1));
}

TEST(BucketTable, CollisionsProbeLinearlyAndWrapAround) {
  const std::size_t k = 4;
  auto z = emptySlots(k);
  // H(3) = H(7) = H(11) = 3 (mod 4), H(2) = 2: 7 and 11 must wrap to slots 0 and 1.
  insertNearest(z, packDepthFirst(10, 3));
  insertNearest(z, packDepthFirst(20, 7));
  insertNearest(z, packDepthFirst(30, 11));
  insertNearest(z, packDepthFirst(40, 2));
  auto table = emptySlots(k);
  ASSERT_EQ(buildBuckets(z, table), 4u);
  EXPECT_EQ(unpackBucket(table[2]).shape, 2);
  EXPECT_EQ(unpackBucket(table[3]).shape, 3);
  EXPECT_EQ(unpackBucket(table[0]).shape, 7);
  EXPECT_EQ(unpackBucket(table[1]).shape, 11);
  for (std::uint16_t s : {2, 3, 7, 11}) {
    const auto b = findBucket(table, s);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->shape, s);
    EXPECT_EQ(b->first, b->last);
    EXPECT_EQ(shapeOfShapeFirst(z[b->first]), s);
  }
  EXPECT_FALSE(findBucket(table, 15)) << "a full table without the shape";
}

TEST(BucketTable, BinarySearchFindsEveryKeptFragmentAndRejectsOthers) {
  const std::size_t k = 8;
  auto z = emptySlots(k);
  for (std::uint16_t d = 1; d <= 10; ++d) insertNearest(z, packDepthFirst(std::uint16_t(d * 10), d % 3));
  auto table = emptySlots(k);
  buildBuckets(z, table);
  for (std::uint16_t d = 1; d <= 10; ++d) {
    const auto b = findBucket(table, d % 3);
    const std::uint32_t key = packShapeFirst(std::uint16_t(d * 10), d % 3);
    const auto at = b ? findInBucket(z, *b, key) : std::nullopt;
    if (d <= 8) {
      ASSERT_TRUE(at) << d;
      EXPECT_EQ(z[*at], key);
    } else {
      EXPECT_FALSE(at) << "depth " << d * 10 << " is beyond the k nearest";
    }
  }
}

// Random pixels of a quad stack: every pixel holds the same quads (as full-screen quads do),
// with small per-pixel perturbations of depth and normal.
TEST(BucketNeighbors, BucketQueryEqualsBruteForceOnRandomQuadStacks) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const std::uint32_t k = 16, layers = 4 + rng() % 28, objects = 1 + rng() % 32;
    std::vector<std::uint16_t> depth(layers), shape(layers);
    for (std::uint32_t i = 0; i < layers; ++i) {
      depth[i] = std::uint16_t(rng() % 60000);
      shape[i] = std::uint16_t(rng() % objects);
    }
    std::vector<ReferencePixel> pixels(2);
    for (auto& px : pixels) {
      auto z = emptySlots(k);
      for (std::uint32_t i = 0; i < layers; ++i)
        insertNearest(z, packDepthFirst(std::uint16_t(depth[i] + rng() % 50), shape[i]));
      px.table = emptySlots(k);
      const auto n = buildBuckets(z, px.table);
      std::uniform_real_distribution<float> tilt(-0.2f, 0.2f);
      for (std::uint32_t i = 0; i < n; ++i)
        px.fragments.push_back({z[i], glm::normalize(glm::vec3(tilt(rng), tilt(rng), 1.0f))});
    }
    for (std::uint32_t i = 0; i < pixels[0].fragments.size(); ++i) {
      const auto a = neighborOf(pixels[0], i, pixels[1], NeighborSearch::Buckets);
      const auto b = neighborOf(pixels[0], i, pixels[1], NeighborSearch::BruteForce);
      EXPECT_EQ(a, b) << "trial " << trial << " fragment " << i;
      if (a) { EXPECT_EQ(shapeOfShapeFirst(pixels[1].fragments[*a].key), shapeOfShapeFirst(pixels[0].fragments[i].key)); }
    }
  }
}

TEST(BucketNeighbors, ReverseCheckRejectsAOneSidedMatch) {
  // Pixel p has two fragments of shape 0 (depth 100 and 120); q has one at depth 118. The one
  // at 100 picks q's fragment, but q's fragment picks 120 back (Fig. 5): no link for 100.
  ReferencePixel p, q;
  p.table = emptySlots(4);
  q.table = emptySlots(4);
  auto zp = emptySlots(4), zq = emptySlots(4);
  insertNearest(zp, packDepthFirst(100 * 256, 0));
  insertNearest(zp, packDepthFirst(120 * 256, 0));
  insertNearest(zq, packDepthFirst(118 * 256, 0));
  buildBuckets(zp, p.table);
  buildBuckets(zq, q.table);
  for (int i = 0; i < 2; ++i) p.fragments.push_back({zp[i], {0, 0, 1}});
  q.fragments.push_back({zq[0], {0, 0, 1}});
  EXPECT_FALSE(neighborOf(p, 0, q, NeighborSearch::Buckets));
  EXPECT_EQ(neighborOf(p, 1, q, NeighborSearch::Buckets), 0u);
}

TEST(ScreenSpaceCurvature, SignFlatAndMissingNeighbours) {
  const glm::vec3 up(0, 0, 1);
  EXPECT_EQ(screenSpaceCurvature(up, up, up, up, 64.0f), 0.0f);
  EXPECT_EQ(screenSpaceCurvature(std::nullopt, up, up, up, 64.0f), -1.0f);
  // A sphere seen from outside: nx grows to the right, ny upwards → convex → negative.
  const float s = 0.01f;
  const auto n = [](float x, float y) { return glm::normalize(glm::vec3(x, y, 1.0f)); };
  const float convex = screenSpaceCurvature(n(-s, 0), n(s, 0), n(0, -s), n(0, s), 64.0f);
  EXPECT_LT(convex, 0.0f);
  EXPECT_NEAR(convex, std::tanh(-64.0f * (n(s, 0).x + n(0, s).y)), 1e-6f);
  EXPECT_GT(screenSpaceCurvature(n(s, 0), n(-s, 0), n(0, s), n(0, -s), 64.0f), 0.0f) << "concave";
}

TEST(TransferFunctions, BuiltinsAndInlinePoints) {
  const auto fig6a = CurvatureShadingFunction::parse("fig6a");
  EXPECT_FLOAT_EQ(fig6a.at(-1).r, 1.0f);
  EXPECT_NEAR(fig6a.at(0).r, 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(fig6a.at(1).r, 0.0f);
  const auto points = CurvatureShadingFunction::parse("points:-1=0.2,1=0.6");
  EXPECT_NEAR(points.at(0).g, 0.4f, 1e-3f);
  const auto fig7a = CurvatureOpacityFunction::parse("fig7a");
  EXPECT_LT(fig7a.at(0, 0), fig7a.at(1, 0)) << "curved more opaque than flat";
  EXPECT_LT(fig7a.at(0, 0), fig7a.at(0, 1)) << "far more opaque than near";
  const auto grid = CurvatureOpacityFunction::parse("grid:0,1/0,1");
  EXPECT_NEAR(grid.at(0.25f, 0.5f), 0.25f, 1e-6f);
  EXPECT_THROW(CurvatureShadingFunction::parse("points:1=0.5,0=0.5"), std::invalid_argument);
  EXPECT_THROW(CurvatureOpacityFunction::parse("grid:0,1/0"), std::invalid_argument);
  EXPECT_THROW(CurvatureOpacityFunction::parse("/no/such/file.png"), std::invalid_argument);
}
