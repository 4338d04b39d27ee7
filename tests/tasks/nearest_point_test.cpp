#include "tasks/nearest_point/nearest_point_task.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene_source.hpp"
#include "task_test_scenes.hpp"
#include "tasks/nearest_point/geodesic_distances.hpp"
#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {
namespace {

// The surface point of `mesh` at the vertex nearest to `p` (as a corner of one of its triangles).
SurfacePoint atVertex(const WeldedMesh& mesh, glm::dvec3 p) {
  std::uint32_t best = 0;
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
    if (glm::length(mesh.positions[v] - p) < glm::length(mesh.positions[best] - p)) best = v;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i)
      if (mesh.triangles[t][i] == best) {
        glm::dvec3 b(0.0);
        b[i] = 1.0;
        return {t, b};
      }
  throw std::logic_error("vertex in no triangle");
}

TEST(GeodesicDistances, FoldedStripPointAcrossTheFoldIsEuclideanNearButGeodesicFar) {
  // Bottom sheet y = 0 and top sheet y = 0.2, both x ∈ [0, 2], joined at x = 2.
  const WeldedMesh mesh = weldMesh(testing::makeFoldedStrip(2.0, 0.2, 8, 4));
  const GeodesicDistances geodesics(mesh);
  const SurfacePoint a = atVertex(mesh, {0.5, 0.0, 0.5});
  const SurfacePoint across = atVertex(mesh, {0.5, 0.2, 0.5});  // straight above A
  const SurfacePoint along = atVertex(mesh, {1.25, 0.0, 0.5});  // on A's own sheet
  const auto d = geodesics.fromSource(a, {across, along});
  ASSERT_TRUE(d[0] && d[1]);
  // Developed, the strip is flat: across = (2 − 0.5) + 0.2 + (2 − 0.5) = 3.2, along = 0.75.
  EXPECT_NEAR(*d[0], 3.2, 1e-6);
  EXPECT_NEAR(*d[1], 0.75, 1e-6);
  EXPECT_LT(glm::length(across.position(mesh) - a.position(mesh)), glm::length(along.position(mesh) - a.position(mesh)));
  EXPECT_GT(*d[0], *d[1]);
}

// An open polygonal cylinder (32 segments, 4 rings of quads), its welded mesh and geodesics.
struct TestCylinder {
  static constexpr int segments = 32;
  render::TriangleMesh source = render::makeOpenCylinder(1.0f, 2.0f, segments, 4);
  WeldedMesh mesh = weldMesh(source);
  GeodesicDistances geodesics{mesh};
  // Ring r, segment s of the source mesh (before welding), as used by makeOpenCylinder.
  glm::dvec3 vertex(int r, int s) const { return glm::dvec3(source.positions[std::size_t(r * (segments + 1) + s)]); }
};

TEST(GeodesicDistances, CylinderMatchesTheUnrolledDistance) {
  // The polygonal cylinder's quads are planar rectangles, so it develops onto a flat strip of
  // width segments × chord: the geodesic between two vertices is √((k · chord)² + Δy²).
  const TestCylinder cylinder;
  const int segments = TestCylinder::segments;
  const WeldedMesh& mesh = cylinder.mesh;
  const GeodesicDistances& geodesics = cylinder.geodesics;
  const auto vertex = [&](int r, int s) { return cylinder.vertex(r, s); };
  const SurfacePoint a = atVertex(mesh, vertex(0, 3));
  struct Case { int r, s; };
  for (const Case c : {Case{4, 3}, Case{2, 9}, Case{4, 14}, Case{1, 19}, Case{3, 30}, Case{0, 10}}) {
    const SurfacePoint b = atVertex(mesh, vertex(c.r, c.s));
    // Perimeter distance the shorter way round, summing the actual (float) chords.
    const int k = std::min(std::abs(c.s - 3), segments - std::abs(c.s - 3));
    const int step = (c.s - 3 + segments) % segments <= segments / 2 ? 1 : -1;
    double around = 0.0;
    for (int i = 0, s = 3; i < k; ++i, s = (s + step + segments) % segments)
      around += glm::length(vertex(0, (s + step + segments) % segments) - vertex(0, s));
    const double dy = vertex(c.r, c.s).y - vertex(0, 3).y;
    const double expected = std::sqrt(around * around + dy * dy);
    const auto d = geodesics.fromSource(a, {b});
    ASSERT_TRUE(d[0]);
    EXPECT_NEAR(*d[0] / expected, 1.0, 1e-6) << "ring " << c.r << " segment " << c.s;
  }
}

TEST(GeodesicDistances, CappedDistancesAreExactWithinTheCapAndLowerBoundsBeyond) {
  // On the unrolled cylinder, distances from one vertex to every other ring/segment vertex: the
  // capped computation must agree exactly below the cap and never exceed the truth beyond it.
  const TestCylinder cylinder;
  const WeldedMesh& mesh = cylinder.mesh;
  const GeodesicDistances& geodesics = cylinder.geodesics;
  const SurfacePoint a = atVertex(mesh, cylinder.vertex(0, 3));
  std::vector<SurfacePoint> targets;
  for (int r = 0; r <= 4; ++r)
    for (int s = 0; s < TestCylinder::segments; s += 3) targets.push_back(atVertex(mesh, cylinder.vertex(r, s)));
  const auto full = geodesics.fromSource(a, targets);
  const double cap = 1.2;
  const auto capped = geodesics.fromSourceWithin(a, targets, cap);
  int exact = 0, bounded = 0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    ASSERT_TRUE(full[i].has_value());
    ASSERT_TRUE(capped[i].reachable);
    const double euclidean = glm::length(targets[i].position(mesh) - a.position(mesh));
    if (*full[i] < cap * (1 - 1e-9)) {
      ASSERT_TRUE(capped[i].exact.has_value()) << "target " << i << " at " << *full[i];
    }
    if (capped[i].exact) {
      ++exact;
      EXPECT_NEAR(*capped[i].exact, *full[i], 1e-9 * *full[i] + 1e-12);
      EXPECT_LE(*capped[i].exact, cap);
    } else {
      ++bounded;
      EXPECT_LE(capped[i].lowerBound, *full[i] * (1 + 1e-12));
      EXPECT_GE(capped[i].lowerBound, std::max(cap, euclidean) * (1 - 1e-12));
    }
  }
  EXPECT_GT(exact, 3);
  EXPECT_GT(bounded, 10);
}

TEST(GeodesicDistances, OtherComponentIsUnreachable) {
  render::TriangleMesh two = render::makeQuad({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  render::appendMesh(two, render::makeQuad({5, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  const WeldedMesh mesh = weldMesh(two);
  const GeodesicDistances geodesics(mesh);
  const auto d = geodesics.fromSource({0, {1.0 / 3, 1.0 / 3, 1.0 / 3}}, {{1, {1.0 / 3, 1.0 / 3, 1.0 / 3}}, {2, {1.0 / 3, 1.0 / 3, 1.0 / 3}}});
  EXPECT_TRUE(d[0].has_value());
  EXPECT_FALSE(d[1].has_value());
}

TEST(NearestPoint, TrapShareIsSpreadEvenlyAndIndependentOfTheCount) {
  int traps = 0;
  for (int k = 0; k < 10; ++k) traps += wantsEuclideanTrap(k, 0.3);
  EXPECT_EQ(traps, 3);
  for (int k = 0; k < 10; ++k) {
    EXPECT_FALSE(wantsEuclideanTrap(k, 0.0));
    EXPECT_TRUE(wantsEuclideanTrap(k, 1.0));
  }
  EXPECT_TRUE(wantsEuclideanTrap(1, 0.5));
  EXPECT_FALSE(wantsEuclideanTrap(0, 0.5));
}

// A scene of the folded strip seen from the side, where the two sheets are apart on screen.
render::Scene foldedStripScene() {
  render::Scene scene;
  scene.objects.push_back(testing::makeObject("strip", testing::makeFoldedStrip(2.0, 0.6, 10, 4), render::Role::Transparent));
  render::Camera camera;
  camera.eye = {1.0, 0.8, 4.0};
  camera.target = {1.0, 0.3, 0.5};
  camera.nearPlane = 0.5f;
  camera.farPlane = 10.0f;
  scene.camera = camera;
  return scene;
}

TEST(NearestPoint, QuestionsOnTheFoldedStripMeetTheMarginsAndTheTrapShare) {
  const render::Scene scene = foldedStripScene();
  const NearestPointTask task;
  const auto questions = task.probe({scene, *scene.camera, 400, 400, 6, 9, task.settings({"euclidean-trap-share=0.5"})});
  ASSERT_EQ(questions.size(), 6u);
  const WeldedMesh mesh = weldMesh(scene.objects[0].mesh);
  int traps = 0;
  for (const auto& q : questions) {
    // Recompute every distance from the printed points and check the rules on them.
    const glm::dvec3 a = q.points.at(0).world;
    // Exact distances for the nearest (and candidates near A), proven lower bounds for the rest.
    std::vector<double> geo, euc;
    std::vector<bool> exact;
    for (std::size_t i = 1; i < q.points.size(); ++i) {
      const auto named = [&](const std::string& key) {
        return std::find_if(q.measurements.begin(), q.measurements.end(), [&](const auto& m) { return m.first == key + q.points[i].label; });
      };
      auto it = named("geodesic:");
      exact.push_back(it != q.measurements.end());
      if (!exact.back()) it = named("geodesic-lower-bound:");
      ASSERT_NE(it, q.measurements.end());
      geo.push_back(it->second);
      euc.push_back(glm::length(q.points[i].world - a));
    }
    const std::size_t g = std::size_t(std::min_element(geo.begin(), geo.end()) - geo.begin());
    ASSERT_TRUE(exact[g]) << "the nearest candidate's distance must be exact";
    const std::size_t e = std::size_t(std::min_element(euc.begin(), euc.end()) - euc.begin());
    EXPECT_EQ(std::get<std::string>(q.truth), q.points[1 + g].label);
    for (std::size_t i = 0; i < geo.size(); ++i)
      if (i != g) {
        EXPECT_GE(geo[i], 1.1 * geo[g] * (1 - 1e-12)) << "question " << q.number;
      }
    const bool trap = g != e;
    EXPECT_EQ(trap, wantsEuclideanTrap(q.number - 1, 0.5)) << "question " << q.number;
    traps += trap;
  }
  EXPECT_EQ(traps, 3);
}

TEST(NearestPoint, SphereCannotHaveAEuclideanTrap) {
  // On a sphere the geodesic distance grows with the chord: the Euclidean-nearest is always the
  // geodesic-nearest, so demanding a trap must fail with a message saying so.
  const render::Scene scene = render::loadScene("builtin:sphere?segments=24&rings=12");
  const NearestPointTask task;
  const auto camera = render::fitCamera(scene.boundingSphere(), 1.0f);
  try {
    task.probe({scene, camera, 256, 256, 1, 1, task.settings({"euclidean-trap-share=1", "sources=4"})});
    FAIL() << "expected no question";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("euclidean-trap-share=0"), std::string::npos) << e.what();
  }
  EXPECT_EQ(task.probe({scene, camera, 256, 256, 2, 1, task.settings({"euclidean-trap-share=0"})}).size(), 2u);
}

}  // namespace
}  // namespace tlab::tasks
