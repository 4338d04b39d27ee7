// The advancing front (Hultquist, Garth refinement): resolution bounds, triangle quality, (s, t)
// along particle tracks, and geometric accuracy on a field with known stream lines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "stimuli/fields/double_gyre.hpp"
#include "stimuli/fields/linear_saddle.hpp"
#include "stimuli/fields/solid_rotation.hpp"
#include "stimuli/fields/vortex_ring.hpp"
#include "stimuli/surfaces/advancing_front.hpp"

namespace tlab::stimuli {
namespace {

IntegratorSettings dopri() {
  IntegratorSettings s;
  s.kind = IntegratorKind::DormandPrince;
  s.step = 0.01;
  s.absoluteTolerance = s.relativeTolerance = 1e-8;
  return s;
}

AdvancingFrontSettings front(double maxSpacing, int steps, double dt) {
  AdvancingFrontSettings f;
  f.maxSpacing = maxSpacing;
  f.minSpacing = 0.3 * maxSpacing;
  f.steps = steps;
  f.timeStep = dt;
  f.maxParticles = 5000;
  return f;
}

void expectNoDegenerateTriangles(const render::TriangleMesh& mesh) {
  ASSERT_FALSE(mesh.triangles.empty());
  for (const auto& t : mesh.triangles) {
    ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const float area2 = glm::length(glm::cross(b - a, c - a));
    const float longest2 = std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
    ASSERT_GT(area2, 1e-6f * longest2);
  }
}

// Along every particle's track, s is constant and t strictly increases.
void expectMonotoneTracks(const IntegralSurface& surface) {
  ASSERT_FALSE(surface.tracks.empty());
  for (const auto& track : surface.tracks)
    for (std::size_t k = 1; k < track.size(); ++k) {
      const glm::vec2 prev = surface.mesh.st[track[k - 1]], cur = surface.mesh.st[track[k]];
      ASSERT_EQ(prev.x, cur.x);
      ASSERT_GT(cur.y, prev.y);
    }
}

TEST(AdvancingFront, DivergingFrontIsRefinedToTheMaximumSpacing) {
  const LinearSaddle saddle(1.0, 0.0);  // x stretches by e^t
  const AdvancingFrontSettings f = front(0.05, 40, 0.05);
  const IntegralSurface s = streamSurface(saddle, SeedCurve::line({-0.5, 0.2, 0.0}, {0.5, 0.2, 0.0}), 0.0, dopri(), f);
  std::size_t inserted = 0;
  for (const auto& stats : s.fronts) {
    EXPECT_LE(stats.maxSpacing, f.maxSpacing * (1.0 + 1e-9)) << "front " << stats.step;
    inserted += stats.inserted;
  }
  EXPECT_GT(inserted, 50u);
  // The front grew from length 1 to e² ≈ 7.4: its particle count follows.
  EXPECT_GE(s.fronts.back().particles, std::size_t(std::exp(2.0) / f.maxSpacing));
  expectNoDegenerateTriangles(s.mesh);
  expectMonotoneTracks(s);
}

TEST(AdvancingFront, ConvergingFrontIsThinnedToTheMinimumSpacing) {
  const LinearSaddle saddle(1.0, 0.0);  // y contracts by e^−t
  const AdvancingFrontSettings f = front(0.05, 40, 0.05);
  const IntegralSurface s = streamSurface(saddle, SeedCurve::line({0.2, -1.0, 0.0}, {0.2, 1.0, 0.0}), 0.0, dopri(), f);
  std::size_t removed = 0;
  for (const auto& stats : s.fronts) removed += stats.removed;
  EXPECT_GT(removed, 10u);
  // Final front length 2e^−2 ≈ 0.27: no more than about one particle per minSpacing.
  const double length = 2.0 * std::exp(-2.0);
  EXPECT_LE(double(s.fronts.back().particles), 2.0 * length / f.minSpacing + 2.0);
  for (const auto& stats : s.fronts) EXPECT_LE(stats.maxSpacing, f.maxSpacing * (1.0 + 1e-9));
  expectNoDegenerateTriangles(s.mesh);
  expectMonotoneTracks(s);
}

TEST(AdvancingFront, StreamSurfaceOfARotationIsTheSweptAnnulus) {
  const SolidRotation rotation(1.0);
  const IntegralSurface s =
      streamSurface(rotation, SeedCurve::line({0.5, 0.0, 0.0}, {1.0, 0.0, 0.0}), 0.0, dopri(), front(0.04, 60, 0.05));
  for (std::size_t i = 0; i < s.mesh.positions.size(); ++i) {
    const glm::vec3 p = s.mesh.positions[i];
    const double radius = std::hypot(p.x, p.y);
    // The radius of a vertex is fixed by its seed parameter s: r = 0.5 + 0.5 s.
    EXPECT_NEAR(radius, 0.5 + 0.5 * s.mesh.st[i].x, 1e-5);
    EXPECT_NEAR(p.z, 0.0, 1e-6);
    EXPECT_NEAR(std::atan2(p.y, p.x), s.mesh.st[i].y, 1e-4);  // angle = ω t
  }
  expectNoDegenerateTriangles(s.mesh);
}

TEST(AdvancingFront, CurvatureRefinementAddsParticlesWhereTheFrontBends) {
  const VortexRing ring;  // differential rotation about the core rolls the seed line into a spiral
  AdvancingFrontSettings loose = front(0.15, 40, 0.05);
  loose.maxBendDegrees = 180.0;  // spacing only
  AdvancingFrontSettings tight = loose;
  tight.maxBendDegrees = 10.0;
  const SeedCurve seed = SeedCurve::line({0.7, 0.0, 0.0}, {1.3, 0.0, 0.0});
  const IntegralSurface a = streamSurface(ring, seed, 0.0, dopri(), loose);
  const IntegralSurface b = streamSurface(ring, seed, 0.0, dopri(), tight);
  EXPECT_GT(b.fronts.back().particles, a.fronts.back().particles);
  expectNoDegenerateTriangles(b.mesh);
  expectMonotoneTracks(b);
}

TEST(AdvancingFront, PathSurfaceOfTheTimeDependentDoubleGyre) {
  const DoubleGyre gyre;
  const IntegralSurface s =
      pathSurface(gyre, SeedCurve::line({0.2, 0.3, 0.0}, {1.8, 0.3, 0.0}), 0.0, dopri(), front(0.05, 80, 0.1));
  // Space-time extrusion: a vertex's height is climb · t.
  for (std::size_t i = 0; i < s.mesh.positions.size(); ++i) EXPECT_NEAR(s.mesh.positions[i].z, 0.1 * s.mesh.st[i].y, 1e-5);
  expectNoDegenerateTriangles(s.mesh);
  expectMonotoneTracks(s);
  EXPECT_EQ(s.fronts.size(), 81u);
}

TEST(AdvancingFront, TheFrontTearsWhereParticlesLeaveTheDomain) {
  // The rotation's domain is [-10, 10]³; a seed reaching outside it loses its outer particles.
  const SolidRotation rotation(1.0);
  const IntegralSurface s =
      streamSurface(rotation, SeedCurve::line({9.0, 0.0, 0.0}, {11.0, 0.0, 0.0}), 0.0, dopri(), front(0.2, 20, 0.05));
  for (const auto& p : s.mesh.positions) EXPECT_LE(std::abs(p.x), 11.0f);
  EXPECT_LT(s.fronts.back().particles, s.fronts.front().particles);
}

}  // namespace
}  // namespace tlab::stimuli
