#include "tasks/follow_boundary/follow_boundary_task.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene_source.hpp"
#include "tasks/follow_boundary/boundary_arc.hpp"
#include "tasks/follow_boundary/boundary_loops.hpp"
#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {
namespace {

constexpr double kPi = std::numbers::pi;

// The arc position of the loop vertex nearest to `p`.
double arcOfVertex(const BoundaryLoop& loop, glm::dvec3 p) {
  double arc = 0.0, best = 1e9, bestArc = 0.0;
  const auto& pts = loop.points();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (glm::length(pts[i] - p) < best) best = glm::length(pts[i] - p), bestArc = arc;
    arc += glm::length(pts[(i + 1) % pts.size()] - pts[i]);
  }
  return bestArc;
}

// The rim point of the open cylinder at angle φ (the mesh uses (cos φ, y, −sin φ)).
glm::dvec3 rim(double phi, double y) { return {std::cos(phi), y, -std::sin(phi)}; }

TEST(BoundaryLoops, OpenCylinderHasTwoRimLoopsOfPolygonLength) {
  const WeldedMesh mesh = weldMesh(render::makeOpenCylinder(1.0f, 2.0f, 64, 3));
  const auto loops = boundaryLoops(mesh, 0);
  ASSERT_EQ(loops.size(), 2u);
  const double polygon = 64 * 2.0 * std::sin(kPi / 64);
  for (const auto& l : loops) {
    EXPECT_EQ(l.points().size(), 64u);
    EXPECT_NEAR(l.length(), polygon, 1e-5);
    EXPECT_NEAR(std::abs(l.points()[0].y), 1.0, 1e-6);
  }
  EXPECT_TRUE(boundaryLoops(weldMesh(render::makeUvSphere(1.0f, 16, 8)), 0).empty());
}

TEST(BoundaryArc, ShorterDirectionIsChosenAndOtherArcLabelsAreNotMet) {
  const WeldedMesh mesh = weldMesh(render::makeOpenCylinder(1.0f, 2.0f, 64, 3));
  const auto loops = boundaryLoops(mesh, 0);
  const BoundaryLoop& top = loops[0].points()[0].y > 0 ? loops[0] : loops[1];
  const double step = 2.0 * kPi / 64;
  const double a = arcOfVertex(top, rim(0.0, 1.0)), b = arcOfVertex(top, rim(18 * step, 1.0));  // ~101°
  for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
    const BoundaryArc way = shortestBoundaryArc(from, to, top.length());
    EXPECT_NEAR(way.length, 18 * 2.0 * std::sin(kPi / 64), 1e-5);
    EXPECT_TRUE(way.contains(arcOfVertex(top, rim(9 * step, 1.0))));    // between A and B the short way
    EXPECT_FALSE(way.contains(arcOfVertex(top, rim(40 * step, 1.0))));  // on the other arc
    EXPECT_FALSE(way.contains(arcOfVertex(top, rim(-5 * step, 1.0))));
    EXPECT_FALSE(way.contains(from));  // the ends are not "met on the way"
    EXPECT_FALSE(way.contains(to));
  }
  // Going past the half: the way turns round.
  const double c = arcOfVertex(top, rim(40 * step, 1.0));
  const BoundaryArc back = shortestBoundaryArc(a, c, top.length());
  EXPECT_NEAR(back.length, 24 * 2.0 * std::sin(kPi / 64), 1e-5);
  EXPECT_TRUE(back.contains(arcOfVertex(top, rim(50 * step, 1.0))));
  EXPECT_FALSE(back.contains(arcOfVertex(top, rim(20 * step, 1.0))));
}

TEST(BoundaryArc, PointAtFollowsTheLoop) {
  const BoundaryLoop square({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 0);
  EXPECT_DOUBLE_EQ(square.length(), 4.0);
  EXPECT_EQ(square.pointAt(1.5), glm::dvec3(1.0, 0.5, 0.0));
  EXPECT_EQ(square.pointAt(-0.25), glm::dvec3(0.0, 0.25, 0.0));
  EXPECT_EQ(square.pointAt(4.5), glm::dvec3(0.5, 0.0, 0.0));
}

// The angle of a rim point, in [0, 2π).
double angleOf(glm::dvec3 p) {
  const double a = std::atan2(-p.z, p.x);
  return a < 0 ? a + 2 * kPi : a;
}

TEST(FollowBoundary, GroundTruthIsTheMarksOnTheShorterArcOfTheRim) {
  // Independent check by angles: on a circular rim the shorter way by arc length is the shorter
  // way by angle (the margin keeps the polygon's deviation from deciding).
  const render::Scene scene = render::loadScene("builtin:open-cylinders");
  const FollowBoundaryTask task;
  const auto questions = task.probe({scene, *scene.camera, 512, 512, 8, 3, task.settings({})});
  ASSERT_EQ(questions.size(), 8u);
  int marksOnTheWay = 0, marksOffTheWay = 0;
  for (const auto& q : questions) {
    const ProbePoint& A = q.points[0];
    const ProbePoint& B = q.points[1];
    EXPECT_EQ(A.role, "start");
    EXPECT_EQ(B.role, "end");
    EXPECT_NEAR(A.world.y, B.world.y, 1e-9);  // one loop
    const double a = angleOf(A.world), b = angleOf(B.world);
    const double forward = std::fmod(b - a + 4 * kPi, 2 * kPi);
    std::set<std::string> expected;
    for (std::size_t i = 2; i < q.points.size(); ++i) {
      const ProbePoint& m = q.points[i];
      const bool sameLoop = m.object == A.object && std::abs(m.world.y - A.world.y) < 1e-9;
      const double t = std::fmod(angleOf(m.world) - a + 4 * kPi, 2 * kPi);
      const bool between = forward <= kPi ? (t > 0 && t < forward) : (t > forward && t < 2 * kPi);
      if (sameLoop && between) expected.insert(m.label);
    }
    EXPECT_EQ(std::get<std::set<std::string>>(q.truth), expected) << "question " << q.number;
    marksOnTheWay += int(expected.size());
    marksOffTheWay += int(q.points.size() - 2 - expected.size());
    EXPECT_GE(expected.size(), 1u);
    EXPECT_LT(expected.size(), q.points.size() - 2);
  }
  EXPECT_GT(marksOnTheWay, 0);
  EXPECT_GT(marksOffTheWay, 0);
}

TEST(FollowBoundary, ClosedSurfaceHasNoBoundaryQuestion) {
  const render::Scene scene = render::loadScene("builtin:sphere?segments=16&rings=8");
  const FollowBoundaryTask task;
  EXPECT_THROW(task.probe({scene, render::fitCamera(scene.boundingSphere(), 1.0f), 256, 256, 1, 1, task.settings({})}),
               std::runtime_error);
}

}  // namespace
}  // namespace tlab::tasks
