// Dynamic transparency (Elmqvist et al., seed 004) without GL: the alpha mask of Algs. 2-3 and
// Fig. 2, and the frame-coherent back-to-front group order of Sec. V.2.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/ops/alpha_mask.hpp"
#include "renderer/ops/group_draw_order.hpp"
#include "renderer/scene/builtin_scenes.hpp"

using namespace tlab::render;

namespace {

// A square target of side `side` cells centred in a size x size grid at depth 5.
TargetCoverage square(int size, int lo, int hi) {
  TargetCoverage c;
  c.size = size;
  c.target.assign(std::size_t(size * size), 0u);
  c.depth.assign(c.target.size(), 0.0f);
  for (int y = lo; y < hi; ++y)
    for (int x = lo; x < hi; ++x) {
      c.target[std::size_t(y * size + x)] = 1u;
      c.depth[std::size_t(y * size + x)] = 5.0f;
    }
  return c;
}

SceneObject boxAt(glm::vec3 centre, Role roles = Role::Distractor, int group = -1) {
  SceneObject o;
  o.mesh = makeBox(glm::vec3(0.5f));
  transformMesh(o.mesh, glm::translate(glm::mat4(1.0f), centre));
  o.roles = roles;
  o.group = group;
  return o;
}

}  // namespace

TEST(AlphaMask, BorderAlphaRisesFromAlpha0ToOneOverNLayers) {
  EXPECT_FLOAT_EQ(borderAlpha(1, 4, 0.2f), 0.2f);
  EXPECT_FLOAT_EQ(borderAlpha(4, 4, 0.2f), 0.2f + 0.8f * 3.0f / 4.0f);
  EXPECT_FLOAT_EQ(borderAlpha(5, 4, 0.2f), 1.0f);
  EXPECT_FLOAT_EQ(borderAlpha(0, 4, 0.2f), 1.0f);
}

TEST(AlphaMask, OutlineMaskIsAlphaTOnTheTargetAndAMonotoneGradientOfNCells) {
  AlphaMaskSettings s;
  s.border = 5;
  s.alphaTarget = 0.5f;
  s.alpha0 = 0.1f;
  const AlphaMask m = buildAlphaMask(square(32, 10, 16), s, 1.0f);
  const int y = 13;
  EXPECT_FLOAT_EQ(m.alphaAt(15, y), 0.5f);  // on the target
  EXPECT_FLOAT_EQ(m.depth[std::size_t(y * 32 + 15)], 5.0f);
  float previous = 0.0f;
  for (int i = 1; i <= s.border; ++i) {
    const float a = m.alphaAt(15 + i, y);
    EXPECT_FLOAT_EQ(a, 0.1f + 0.9f * float(i - 1) / 5.0f) << "layer " << i;
    EXPECT_GT(a, previous);
    previous = a;
    EXPECT_FLOAT_EQ(m.depth[std::size_t(y * 32 + 15 + i)], 5.0f);  // the border knows its target's depth
  }
  EXPECT_FLOAT_EQ(m.alphaAt(15 + s.border + 1, y), 1.0f);
  EXPECT_FLOAT_EQ(m.alphaAt(10 - s.border, 10 - s.border), 0.1f + 0.9f * 4.0f / 5.0f);  // 8-neighbour growth: diagonal
}

TEST(AlphaMask, CircleAndEllipseContainTheTargetAndFallOffMonotonically) {
  for (MaskShape shape : {MaskShape::Circle, MaskShape::Ellipse}) {
    AlphaMaskSettings s;
    s.shape = shape;
    s.border = 4;
    s.alphaTarget = 0.4f;
    s.alpha0 = 0.2f;
    const AlphaMask m = buildAlphaMask(square(64, 20, 30), s, 1.0f);
    for (int y = 20; y < 30; ++y)
      for (int x = 20; x < 30; ++x) EXPECT_FLOAT_EQ(m.alphaAt(x, y), 0.4f);
    // Along the row: α_T inside the shape, then the border from α_0 (here below α_T, as the
    // paper advises) rising monotonically to 1.
    int x = 30;
    while (x < 64 && m.alphaAt(x, 25) == 0.4f) ++x;
    EXPECT_FLOAT_EQ(m.alphaAt(x, 25), 0.2f);
    for (float previous = 0.2f; x < 64; ++x) {
      EXPECT_GE(m.alphaAt(x, 25), previous);
      previous = m.alphaAt(x, 25);
    }
    EXPECT_FLOAT_EQ(m.alphaAt(63, 25), 1.0f);
    // Both shapes reach beyond the square's sides (radius √2 times the half extent).
    EXPECT_FLOAT_EQ(m.alphaAt(30, 25), 0.4f);
  }
}

TEST(AlphaMask, CoverageKeepsTheFarthestTargetOfACell) {
  const std::vector<std::uint32_t> targets = {0, 3, 2, 0};
  const std::vector<float> depths = {0, 4.0f, 7.0f, 0};
  const TargetCoverage c = TargetCoverage::fromPixels(4, 1, targets, depths, 1);
  EXPECT_EQ(c.target[0], 2u);
  EXPECT_FLOAT_EQ(c.depth[0], 7.0f);
}

TEST(GroupDrawOrder, SortsGroupsBackToFrontAndKeepsTheOrderWhenTheViewStays) {
  Scene scene;
  scene.objects = {boxAt({0, 0, 0}), boxAt({0, 0, -5}), boxAt({0, 0, 5})};
  GroupDrawOrder order(scene);
  const glm::vec3 eye(0, 0, 20), forward(0, 0, -1);
  EXPECT_GT(order.update(eye, forward), 0u);
  EXPECT_EQ(order.objectRanks(), (std::vector<std::uint32_t>{1, 0, 2}));  // farthest (z = -5) first
  EXPECT_EQ(order.update(eye, forward), 0u);  // frame coherence: nothing to re-sort
  EXPECT_EQ(order.update(glm::vec3(0, 0, -20), -forward), 3u);  // the view turned: full reversal
  EXPECT_EQ(order.objectRanks(), (std::vector<std::uint32_t>{1, 2, 0}));
}

TEST(GroupDrawOrder, GroupsKeepTheirInternalOrderAndImpenetrableObjectsComeFirst) {
  Scene scene;
  // A group {inner, outer}: the outer member is nearer the eye, yet the group order is fixed.
  scene.objects = {boxAt({0, 0, -1}, Role::Target, 7), boxAt({0, 0, 3}, Role::Distractor, 7), boxAt({0, 0, -9}),
                   boxAt({0, 0, 8}, Role::Impenetrable)};
  GroupDrawOrder order(scene);
  order.update({0, 0, 20}, {0, 0, -1});
  EXPECT_EQ(order.groupCount(), 3u);
  EXPECT_EQ(order.objectRanks(), (std::vector<std::uint32_t>{2, 3, 1, 0}));
}
