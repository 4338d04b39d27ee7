// The bucketed k-buffer on the GPU (seed 002, Sec. 4-5) against its CPU model
// (kbuffer/bucket_table.hpp) and against analytic expectations: the k nearest quads per pixel,
// buckets equal to the CPU reorder, neighbours with buckets equal to brute force, κ on spheres
// and on a flat quad.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/kbuffer/bucket_table.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene_source.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;
using namespace tlab::render::kbuffer;

namespace {

RenderRequest curvatureRequest(int size, std::map<std::string, std::string> settings) {
  RenderRequest r;
  r.width = r.height = size;
  r.style = "curvature";
  r.settings = std::move(settings);
  return r;
}

// (depth16, shape) of every quad of a quad-stack scene: the eye is at z = 5, near 1, far 10.
std::vector<std::uint32_t> expectedQuadKeys(const Scene& scene) {
  std::vector<std::uint32_t> keys;
  for (std::size_t o = 0; o < scene.objects.size(); ++o)
    for (std::size_t v = 0; v < scene.objects[o].mesh.positions.size(); v += 4) {
      const float eyeDepth = 5.0f - scene.objects[o].mesh.positions[v].z;
      keys.push_back(packDepthFirst(quantizeDepth((eyeDepth - 1.0f) / 9.0f), std::uint16_t(o)));
    }
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace

TEST(BucketedKBufferGl, KeepsTheKNearestQuadsAndBuildsTheBucketsOfTheCpuModel) {
  const Scene scene = loadScene("builtin:quad-stack?n=20&m=5&seed=3");
  Renderer renderer(scene);
  const int size = 16;
  const std::uint32_t k = 16;
  renderer.render(curvatureRequest(size, {{"k", "16"}, {"mode", "shading"}}));
  const BucketedKBuffer* kb = renderer.kBuffer();
  ASSERT_NE(kb, nullptr);
  const auto z = kb->zRecords();
  const auto table = kb->bucketTable();
  const auto data = kb->dataRecords();
  auto expected = expectedQuadKeys(scene);
  expected.resize(k);  // the 16 nearest of 20
  for (int p = 0; p < size * size; ++p) {
    std::vector<std::uint32_t> pz(z.begin() + p * k, z.begin() + (p + 1) * k);
    ASSERT_TRUE(std::is_sorted(pz.begin(), pz.end())) << "pixel " << p << ": Z is sorted by shape, then depth";
    // Back to depth-first keys: the 16 nearest quads (depth within one quantization step).
    std::vector<std::uint32_t> depthFirst;
    for (auto key : pz) depthFirst.push_back(swapHalves(key));
    std::sort(depthFirst.begin(), depthFirst.end());
    for (std::uint32_t i = 0; i < k; ++i) {
      EXPECT_EQ(depthFirst[i] & 0xFFFFu, expected[i] & 0xFFFFu) << "pixel " << p << " layer " << i;
      EXPECT_LE(std::abs(int(depthFirst[i] >> 16) - int(expected[i] >> 16)), 1) << "pixel " << p << " layer " << i;
    }
    // The CPU model builds the same bucket table from the same fragments.
    std::vector<std::uint32_t> cpuZ = depthFirst, cpuTable(k, kEmpty);
    buildBuckets(cpuZ, cpuTable);
    EXPECT_EQ(cpuZ, pz) << "pixel " << p;
    EXPECT_EQ(std::vector<std::uint32_t>(table.begin() + p * k, table.begin() + (p + 1) * k), cpuTable) << "pixel " << p;
    // The data pass found a slot for every kept fragment (opaque colour byte set).
    for (std::uint32_t i = 0; i < k; ++i) EXPECT_EQ(data[2 * (p * k + i)] >> 24, 255u) << "pixel " << p << " slot " << i;
  }
}

TEST(BucketedKBufferGl, BucketNeighboursEqualBruteForceOnRandomQuadStacks) {
  for (int m : {1, 3, 8, 32}) {
    for (int seed : {1, 2}) {
      const Scene scene = loadScene("builtin:quad-stack?n=32&m=" + std::to_string(m) + "&seed=" + std::to_string(seed));
      Renderer renderer(scene);
      const int size = 12;
      renderer.render(curvatureRequest(size, {{"k", "32"}, {"mode", "shading"}, {"query", "buckets"}}));
      const auto buckets = renderer.kBuffer()->neighborLinks();
      renderer.render(curvatureRequest(size, {{"k", "32"}, {"mode", "shading"}, {"query", "brute-force"}}));
      const auto brute = renderer.kBuffer()->neighborLinks();
      EXPECT_EQ(buckets, brute) << "m=" << m << " seed=" << seed;
      // Every pixel holds the same 32 full-screen quads in the same order, so inside the image
      // each fragment's neighbour in every direction is the same layer; at the border it is missing.
      const auto z = renderer.kBuffer()->zRecords();
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
          for (std::uint32_t layer = 0; layer < 32; ++layer) {
            const std::uint32_t links = buckets[(y * size + x) * 32 + layer];
            const bool inside[4] = {x > 0, x < size - 1, y > 0, y < size - 1};
            for (int d = 0; d < 4; ++d)
              EXPECT_EQ((links >> (8 * d)) & 0xFFu, inside[d] ? layer : 0xFFu)
                  << "m=" << m << " pixel " << x << "," << y << " layer " << layer << " direction " << d;
          }
    }
  }
}

namespace {

// On the z axis at `distance` looking at the origin, with the given clip planes.
Camera onTheZAxis(float distance, float nearPlane, float farPlane) {
  Camera camera;
  camera.eye = {0, 0, distance};
  camera.nearPlane = nearPlane;
  camera.farPlane = farPlane;
  return camera;
}

// Mean |κ| over the fragments with all four neighbours, for a sphere of radius r seen from a
// fixed camera (so a larger sphere bends less). Two tiny quads out of view at (±3, ±3, ±3) keep
// the scene's bounding radius — κ's length unit — the same for every r.
double meanInteriorCurvature(float radius) {
  Scene scene = buildBuiltinScene("sphere?radius=" + std::to_string(radius) + "&segments=128&rings=64", builtinScenes());
  for (float c : {-3.0f, 3.0f}) scene.objects.push_back({"marker", makeQuad({c, c, c}, {0.01f, 0, 0}, {0, 0.01f, 0})});
  Renderer renderer(scene);
  RenderRequest r = curvatureRequest(96, {{"k", "4"}, {"mode", "shading"}, {"scale", "0.05"}});
  r.camera = onTheZAxis(6, 1, 11);
  renderer.render(r);
  double sum = 0;
  std::size_t n = 0;
  const auto z = renderer.kBuffer()->zRecords();
  const auto kappa = renderer.kBuffer()->curvatureValues();
  for (std::size_t i = 0; i < z.size(); ++i)
    if (z[i] != kEmpty && kappa[i] > -1.0f) {
      sum += std::abs(kappa[i]);
      ++n;
    }
  EXPECT_GT(n, 100u) << "radius " << radius;
  return sum / double(n);
}

}  // namespace

TEST(BucketedKBufferGl, CurvatureOfSpheresDecreasesWithTheRadius) {
  const double small = meanInteriorCurvature(0.5f), medium = meanInteriorCurvature(1.0f), large = meanInteriorCurvature(2.0f);
  EXPECT_GT(small, medium);
  EXPECT_GT(medium, large);
  EXPECT_GT(large, 0.0);
}

// κ1 + κ2 of a sphere of radius R at the point facing the viewer is 2/R; in units of s·r (r the
// scene's bounding radius = R here) κ = tanh(−2s) there, at every image size (Vergne et al. 2009
// screen-space curvature with a resolution-independent length unit).
TEST(BucketedKBufferGl, CurvatureAtTheSphereCentreIsTanhTwoSAtEverySize) {
  Scene scene = buildBuiltinScene("sphere?radius=1&segments=128&rings=64", builtinScenes());
  Renderer renderer(scene);
  for (int size : {48, 96}) {
    RenderRequest r = curvatureRequest(size, {{"k", "4"}, {"mode", "shading"}, {"scale", "0.25"}});
    r.camera = onTheZAxis(4, 1, 8);
    renderer.render(r);
    const auto kappa = renderer.kBuffer()->curvatureValues();
    double sum = 0;
    for (int y = size / 2 - 1; y <= size / 2; ++y)
      for (int x = size / 2 - 1; x <= size / 2; ++x) sum += kappa[std::size_t(y * size + x) * 4];
    EXPECT_NEAR(sum / 4.0, std::tanh(-0.5), 0.03) << size << "x" << size;
  }
}

TEST(BucketedKBufferGl, FlatQuadIsZeroInsideAndMinusOneAtItsEdges) {
  Scene scene;
  scene.objects.push_back({"quad", makeQuad({0, 0, 0}, {0.6f, 0, 0}, {0, 0.4f, 0})});
  Renderer renderer(scene);
  const int size = 48;
  RenderRequest r = curvatureRequest(size, {{"k", "4"}, {"mode", "shading"}});
  r.camera = Camera{};  // eye (0, 0, 3) looking at the origin
  renderer.render(r);
  const auto z = renderer.kBuffer()->zRecords();
  const auto kappa = renderer.kBuffer()->curvatureValues();
  const auto covered = [&](int x, int y) { return x >= 0 && y >= 0 && x < size && y < size && z[(y * size + x) * 4] != kEmpty; };
  int interior = 0, edge = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      if (!covered(x, y)) continue;
      EXPECT_EQ(z[(y * size + x) * 4 + 1], kEmpty) << "one layer";
      const bool inside = covered(x - 1, y) && covered(x + 1, y) && covered(x, y - 1) && covered(x, y + 1);
      EXPECT_EQ(kappa[(y * size + x) * 4], inside ? 0.0f : -1.0f) << x << "," << y;
      (inside ? interior : edge)++;
    }
  EXPECT_GT(interior, 100);
  EXPECT_GT(edge, 20);
}

TEST(BucketedKBufferGl, AllThreeModesDrawTheSphere) {
  Renderer renderer(buildBuiltinScene("sphere", builtinScenes()));
  for (const char* mode : {"plain", "shading", "transparency"}) {
    RenderStats stats;
    const tlab::core::Image image = renderer.render(curvatureRequest(64, {{"mode", mode}}), &stats);
    const glm::vec4 centre = image.at(32, 32), corner = image.at(0, 0);
    EXPECT_EQ(corner, glm::vec4(1, 1, 1, 1)) << mode << ": background";
    EXPECT_LT(centre.b, 0.9f) << mode << ": the orange sphere covers the centre";
    EXPECT_GT(stats.fragments, 2000u) << mode;
  }
}
