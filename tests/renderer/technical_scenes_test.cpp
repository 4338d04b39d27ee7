// The technical-illustration scenes: closed, outward-facing solids with the right roles.
#include <gtest/gtest.h>

#include "renderer/ops/silhouette_edges.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/technical_scenes.hpp"

using namespace tlab::render;

namespace {

// Signed volume by the divergence theorem: positive for a closed, outward-facing mesh.
double signedVolume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += glm::dot(glm::dvec3(m.positions[t[0]]), glm::cross(glm::dvec3(m.positions[t[1]]), glm::dvec3(m.positions[t[2]]))) / 6.0;
  return v;
}

bool closed(const TriangleMesh& m) {
  // A named adjacency: edges() returns a reference into it, and a temporary in the range-for
  // would die before the loop body runs (AddressSanitizer: stack-use-after-scope).
  const EdgeAdjacency adjacency(m);
  for (const auto& e : adjacency.edges())
    if (e.face1 == kNoFace) return false;
  return true;
}

}  // namespace

TEST(TechnicalScenes, MugIsAClosedSolidWithTheVolumeOfItsProfile) {
  const TriangleMesh mug = makeMug(1.0f, 0.8f, 2.0f, 0.25f, 256);
  EXPECT_TRUE(closed(mug));
  const double pi = 3.14159265358979;
  const double expected = pi * 1.0 * 2.0 - pi * 0.64 * (2.0 - 0.25);  // outer cylinder minus the cavity
  EXPECT_NEAR(signedVolume(mug), expected, 0.01 * expected);
  // Normals agree with the winding everywhere.
  for (const auto& t : mug.triangles) {
    const glm::vec3 g = glm::cross(mug.positions[t[1]] - mug.positions[t[0]], mug.positions[t[2]] - mug.positions[t[0]]);
    EXPECT_GT(glm::dot(g, mug.normals[t[0]] + mug.normals[t[1]] + mug.normals[t[2]]), 0.0f);
  }
}

TEST(TechnicalScenes, CappedCylinderAlongAnyAxisIsClosedAndOutward) {
  for (const glm::vec3 b : {glm::vec3(2, 0, 0), glm::vec3(0, -2, 0), glm::vec3(1, 1, 1)}) {
    const TriangleMesh c = makeCappedCylinder({0, 0, 0}, b, 0.5f, 128);
    EXPECT_TRUE(closed(c));
    const double expected = 3.14159265358979 * 0.25 * glm::length(b);
    EXPECT_NEAR(signedVolume(c), expected, 0.01 * expected);
  }
}

TEST(TechnicalScenes, EveryScenePairsTransparentSolidsWithOpaqueOnes) {
  for (const auto& spec : technicalScenes()) {
    std::map<std::string, double> defaults;
    for (const auto& p : spec.params) defaults[p.name] = p.defaultValue;
    const Scene scene = spec.build(defaults);
    int transparent = 0, opaque = 0;
    for (const auto& o : scene.objects) {
      EXPECT_TRUE(closed(o.mesh)) << spec.name << " / " << o.name;
      EXPECT_GT(signedVolume(o.mesh), 0.0) << spec.name << " / " << o.name;
      (hasRole(o.roles, Role::Opaque) ? opaque : transparent)++;
    }
    EXPECT_GE(transparent, 1) << spec.name;
    EXPECT_GE(opaque, 1) << spec.name;
    EXPECT_TRUE(scene.camera.has_value()) << spec.name;
  }
}
