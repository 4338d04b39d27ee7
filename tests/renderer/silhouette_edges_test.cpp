// Object-space silhouette edges (Diepstraten Eq. 1) on meshes with known outlines.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "renderer/ops/segment_bvh.hpp"
#include "renderer/ops/silhouette_edges.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/scene/technical_scenes.hpp"

using namespace tlab::render;

namespace {

// How many silhouette segments meet at each (welded) end point.
std::map<std::tuple<float, float, float>, int> endpointDegrees(const std::vector<SilhouetteSegment>& segments) {
  std::map<std::tuple<float, float, float>, int> degree;
  for (const auto& s : segments)
    for (const glm::vec3& p : {s.p0, s.p1}) ++degree[{p.x, p.y, p.z}];
  return degree;
}

}  // namespace

TEST(SilhouetteEdges, CubeFromAGenericViewHasExactlyItsSixOutlineEdges) {
  const Scene scene = loadScene("builtin:cube");
  const EdgeAdjacency adjacency(scene.objects[0].mesh);
  EXPECT_EQ(adjacency.positions().size(), 8u);  // 24 face vertices welded to the 8 corners
  EXPECT_EQ(adjacency.edges().size(), 18u);     // 12 cube edges + 6 face diagonals
  const auto segments = adjacency.silhouettes(scene.camera->eye);
  ASSERT_EQ(segments.size(), 6u);
  for (const auto& s : segments) EXPECT_NEAR(glm::length(s.p1 - s.p0), 1.0f, 1e-5f);  // cube edges, no diagonal
  // The outline is one closed hexagon: every corner on it has two outline edges, and it skips
  // the corner nearest to the eye and the one farthest from it.
  const auto degree = endpointDegrees(segments);
  EXPECT_EQ(degree.size(), 6u);
  for (const auto& [p, d] : degree) EXPECT_EQ(d, 2);
}

TEST(SilhouetteEdges, NearlyFrontalCubeShowsTheRimOfItsFrontFace) {
  const EdgeAdjacency adjacency(makeBox(glm::vec3(0.5f)));
  // From (0.1, 0.1, 5) only the +z face faces the eye (the eye is inside the slabs |x|, |y| < 0.5),
  // so the outline is that face's four edges.
  const auto segments = adjacency.silhouettes({0.1f, 0.1f, 5.0f});
  ASSERT_EQ(segments.size(), 4u);
  for (const auto& s : segments) {
    EXPECT_FLOAT_EQ(s.p0.z, 0.5f);
    EXPECT_FLOAT_EQ(s.p1.z, 0.5f);
  }
}

TEST(SilhouetteEdges, SphereOutlineIsClosedLoops) {
  const EdgeAdjacency adjacency(makeUvSphere(1.0f, 48, 24));
  const auto segments = adjacency.silhouettes({0.3f, 0.4f, 3.0f});
  ASSERT_GT(segments.size(), 20u);
  for (const auto& [p, d] : endpointDegrees(segments)) EXPECT_EQ(d % 2, 0);
  // Every silhouette edge lies near the tangent cone: |n·(p − o)| small relative to |p − o|.
  for (const auto& s : segments) {
    const glm::vec3 mid = 0.5f * (s.p0 + s.p1), n = glm::normalize(mid);
    EXPECT_LT(std::abs(glm::dot(n, glm::normalize(mid - glm::vec3(0.3f, 0.4f, 3.0f)))), 0.15f);
  }
}

TEST(SilhouetteEdges, BoundaryEdgesOfAnOpenSurfaceAlwaysCount) {
  const EdgeAdjacency adjacency(makeQuad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_EQ(adjacency.silhouettes({0, 0, 5}).size(), 4u);
}

// The BVH's nearest-segment distance equals the brute-force minimum (and saturates at the limit).
TEST(SegmentBvh, NearestDistanceMatchesBruteForce) {
  std::vector<SilhouetteSegment> segments;
  std::uint32_t state = 12345u;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24) * 2.0f - 1.0f;
  };
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 a(next(), next(), next());
    segments.push_back({a, a + 0.1f * glm::vec3(next(), next(), next())});
  }
  const SegmentBvh bvh(segments);
  for (int q = 0; q < 300; ++q) {
    const glm::vec3 p(1.5f * next(), 1.5f * next(), 1.5f * next());
    float brute = INFINITY;
    for (const auto& s : segments) brute = std::min(brute, segmentDistance(p, s.p0, s.p1));
    EXPECT_FLOAT_EQ(bvh.nearestDistance(p, 100.0f), brute);
    EXPECT_FLOAT_EQ(bvh.nearestDistance(p, 0.5f * brute), 0.5f * brute);
  }
  EXPECT_EQ(SegmentBvh({}).nearestDistance({0, 0, 0}, 3.0f), 3.0f);
}

// A shaft whose end lies inside a web (Diepstraten's crank): the end cap's rim is inside the
// other closed part of the mesh and never a silhouette, from any eye; the shaft's long edges
// outside the web still are.
TEST(SilhouetteEdges, EdgesBuriedInsideAnotherClosedPartAreNoSilhouettes) {
  TriangleMesh mesh = makeBox(glm::vec3(0.1f, 0.5f, 0.5f));  // the web, x in [-0.1, 0.1]
  appendMesh(mesh, makeCappedCylinder({-2.0f, 0, 0}, {0.0f, 0, 0}, 0.2f, 16));  // ends at x = 0
  const EdgeAdjacency adjacency(mesh);
  std::size_t buried = 0;
  for (bool b : adjacency.buried()) buried += b ? 1 : 0;
  EXPECT_GE(buried, 16u);  // at least the 16 rim edges of the end cap at x = 0
  for (glm::vec3 eye : {glm::vec3(3, 1, 2), glm::vec3(0.5f, 0, 4), glm::vec3(2, 3, -1)}) {
    bool outside = false;
    for (const auto& s : adjacency.silhouettes(eye)) {
      const glm::vec3 m = 0.5f * (s.p0 + s.p1);
      EXPECT_FALSE(m.x > -0.1f && m.x < 0.1f && std::abs(m.y) < 0.5f && std::abs(m.z) < 0.5f) << "inside the web";
      outside = outside || m.x < -0.5f;
    }
    EXPECT_TRUE(outside) << "the shaft's own silhouette";
  }
}
