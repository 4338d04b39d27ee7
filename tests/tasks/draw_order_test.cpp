// The order in which seeded draws are taken, pinned where code once drew several values inside one
// expression. C++ leaves the order of a call's arguments (and of +'s operands) unspecified: GCC
// took them last to first, clang first to last, so a clang build made other probe points, other
// simulated answers and other scenes from the same seed (found by the clang sanitizer build, whose
// figures differed from the committed hashes). Each expectation below draws from its own
// SeededRandom in the order the GCC builds did, value by value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "renderer/scene/builtin_scenes.hpp"
#include "tasks/answer_form.hpp"
#include "tasks/answers/forms.hpp"
#include "tasks/nearest_point/surface_point.hpp"
#include "tasks/welded_mesh.hpp"

using namespace tlab;
using namespace tlab::tasks;

TEST(DrawOrder, ASurfacePointTakesTheTrianglesHighBitsFirstThenItsBarycentrics) {
  const WeldedMesh mesh = weldMesh(render::makeBox({1.0f, 2.0f, 3.0f}));
  std::vector<double> cumulative;
  double sum = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) cumulative.push_back(sum += mesh.area(t));
  const SurfaceSampler sampler(mesh);
  core::SeededRandom random(20261205), expected(20261205);
  std::set<std::uint32_t> triangles;
  for (int i = 0; i < 40; ++i) {
    const SurfacePoint p = sampler.sample(random);
    const double high = double(expected.bits() >> 8);
    const double low = double(expected.bits() >> 8);
    const double u = (high + low / 16777216.0) / 16777216.0;
    const auto t = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u * sum) - cumulative.begin());
    const double r1 = std::sqrt(double(expected.uniform()));
    const double r2 = double(expected.uniform());
    ASSERT_EQ(p.triangle, std::uint32_t(std::min(t, cumulative.size() - 1))) << "sample " << i;
    EXPECT_EQ(p.barycentric, glm::dvec3(1.0 - r1, r1 * (1.0 - r2), r1 * r2)) << "sample " << i;
    triangles.insert(p.triangle);
  }
  EXPECT_GT(triangles.size(), 6u);  // the draws reach many triangles, so the order of the two bit draws matters
}

TEST(DrawOrder, AGuessedFloorPointDrawsTheSecondCoordinatesNoiseFirst) {
  Question q;
  q.answerKind = AnswerKind::FloorPoint;
  q.truth = glm::dvec2(10.0, -4.0);
  q.correctWithin = 2.0;
  for (std::uint64_t seed : {1u, 2u, 77u}) {
    core::SeededRandom random(seed), expected(seed);
    const std::string guess = floorPointForm().guess(q, random);
    const double dy = standardNormal(expected) * 8.0;  // sd 4 × the correct distance
    const double dx = standardNormal(expected) * 8.0;
    EXPECT_EQ(guess, answerNumber(10.0 + dx) + "," + answerNumber(-4.0 + dy)) << "seed " << seed;
    const std::string known = floorPointForm().known(q, random, 1.0, {});
    const double ky = standardNormal(expected) * 0.5;  // 0.25 × the correct distance
    const double kx = standardNormal(expected) * 0.5;
    EXPECT_EQ(known, answerNumber(10.0 + kx) + "," + answerNumber(-4.0 + ky)) << "seed " << seed;
  }
}
