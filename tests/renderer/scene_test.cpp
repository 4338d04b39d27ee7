#include <gtest/gtest.h>

#include <set>

#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/scene/triangle_mesh.hpp"

using namespace tlab::render;

TEST(BuiltinScenes, NestedSpheresHaveNShellsOfRadiusKOverN) {
  const Scene s = loadScene("builtin:nested-spheres?n=4&segments=16&rings=8");
  ASSERT_EQ(s.objects.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const float expected = float(4 - i) / 4.0f;
    for (const auto& p : s.objects[i].mesh.positions) EXPECT_NEAR(glm::length(p), expected, 1e-5f);
  }
}

TEST(BuiltinScenes, QuadStackCyclesObjectIdsAndUsesDistinctDepths) {
  const Scene s = loadScene("builtin:quad-stack?n=10&m=3&seed=7");
  ASSERT_EQ(s.objects.size(), 3u);
  std::set<float> depths;
  std::size_t quads = 0;
  for (const auto& o : s.objects) {
    quads += o.mesh.triangleCount() / 2;
    for (const auto& p : o.mesh.positions) depths.insert(p.z);
  }
  EXPECT_EQ(quads, 10u);
  EXPECT_EQ(depths.size(), 10u);
  // The same seed gives the same depths; another seed others.
  const Scene again = loadScene("builtin:quad-stack?n=10&m=3&seed=7");
  EXPECT_EQ(again.objects[0].mesh.positions, s.objects[0].mesh.positions);
  const Scene other = loadScene("builtin:quad-stack?n=10&m=3&seed=8");
  EXPECT_NE(other.objects[0].mesh.positions, s.objects[0].mesh.positions);
}

TEST(BuiltinScenes, TorusTriangleParameterSetsTheTessellation) {
  const Scene s = loadScene("builtin:torus?triangles=10000");
  EXPECT_NEAR(double(s.triangleCount()), 10000.0, 500.0);
}

TEST(BuiltinScenes, BadNamesAndParametersAreClearErrors) {
  EXPECT_THROW(loadScene("builtin:teapot"), std::invalid_argument);
  try {
    loadScene("builtin:torus?radius=2");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no parameter 'radius'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(loadScene("builtin:nested-spheres?n=abc"), std::invalid_argument);
  EXPECT_THROW(loadScene("builtin:nested-spheres?n=2.5"), std::invalid_argument);
  EXPECT_THROW(loadScene("builtin:nested-spheres?n=0"), std::invalid_argument);
}

TEST(TriangleMesh, ComponentsWeldSeamsButSeparateSurfaces) {
  // A UV sphere duplicates its seam vertices: still one component after welding.
  const TriangleMesh sphere = makeUvSphere(1.0f, 12, 6);
  const auto c = connectedComponents(sphere);
  EXPECT_EQ(*std::max_element(c.begin(), c.end()), 0u);
  TriangleMesh two = makeQuad({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  appendMesh(two, makeQuad({5, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  const auto c2 = connectedComponents(two);
  EXPECT_EQ(c2[0], 0u);
  EXPECT_EQ(c2[4], 1u);
}

TEST(TriangleMesh, ComputedNormalsOfABoxPointOutward) {
  TriangleMesh box = makeBox(glm::vec3(0.5f));
  const auto given = box.normals;
  computeVertexNormals(box);
  for (std::size_t i = 0; i < given.size(); ++i) EXPECT_NEAR(glm::dot(given[i], box.normals[i]), 1.0f, 1e-5f);
}
