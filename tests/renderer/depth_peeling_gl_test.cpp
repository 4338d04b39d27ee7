// Depth peeling (IRIS Sec. 5.1) against the illustration buffer: the same `constant` image, and
// exactly layers + 1 iterations of the occlusion-query loop.
#include <gtest/gtest.h>

#include <algorithm>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

namespace {

RenderRequest request(const std::string& style, std::map<std::string, std::string> settings, int size = 64) {
  RenderRequest r;
  r.width = r.height = size;
  r.style = style;
  r.settings = std::move(settings);
  return r;
}

RenderRequest peeled(RenderRequest r) {
  r.depthPeeling = true;
  return r;
}

double maxDifference(const tlab::core::Image& a, const tlab::core::Image& b) {
  double d = 0;
  for (std::size_t p = 0; p < a.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) d = std::max(d, double(std::abs(a.pixels[p][c] - b.pixels[p][c])));
  return d;
}

}  // namespace

class PeelMatchesBuffer : public ::testing::TestWithParam<std::string> {};

TEST_P(PeelMatchesBuffer, ConstantImagesAgreeWithinOneStepAndIterationsAreLayersPlusOne) {
  const Scene scene = loadScene(GetParam());
  Renderer buffer(scene);
  Renderer peeler(scene);
  for (const char* lighting : {"headlight", "none"}) {
    const RenderRequest r = request("constant", {{"alpha", "0.3"}, {"lighting", lighting}});
    const tlab::core::Image a = buffer.render(r);
    RenderStats stats;
    const tlab::core::Image b = peeler.render(peeled(r), &stats);
    EXPECT_LE(maxDifference(a, b), 1.0 / 255.0) << GetParam() << " lighting=" << lighting;
    const auto counts = buffer.layerCounts();
    const int layers = *std::max_element(counts.begin(), counts.end());
    EXPECT_EQ(stats.peelIterations, layers + 1) << GetParam();
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PeelMatchesBuffer,
                         ::testing::Values("builtin:nested-spheres?n=3", "builtin:nested-spheres?n=1",
                                           "builtin:quad-stack?n=7"));

TEST(DepthPeeling, EmptyViewTakesOneIteration) {
  Renderer peeler(loadScene("builtin:sphere"));
  RenderRequest r = peeled(request("constant", {}));
  Camera away;
  away.eye = {0, 0, 5};
  away.target = {0, 0, 10};  // looking away from the sphere
  r.camera = away;
  RenderStats stats;
  const tlab::core::Image img = peeler.render(r, &stats);
  EXPECT_EQ(stats.peelIterations, 1);
  EXPECT_NEAR(img.at(10, 10).r, peeler.scene().background.r, 1e-6);
}

TEST(DepthPeeling, LocalStylesAgreeWithTheBufferAwayFromSilhouettes) {
  const Scene scene = loadScene("builtin:nested-spheres?n=2");
  Renderer buffer(scene);
  Renderer peeler(scene);
  const RenderRequest r = request("angle", {{"shading", "phong"}}, 64);
  const tlab::core::Image a = buffer.render(r), b = peeler.render(peeled(r));
  double sum = 0;
  for (std::size_t p = 0; p < a.pixels.size(); ++p) sum += std::abs(a.pixels[p].g - b.pixels[p].g);
  EXPECT_LT(sum / double(a.pixels.size()), 0.01);
}

TEST(DepthPeeling, RejectsStylesThatAreNotLocal) {
  Renderer peeler(loadScene("builtin:sphere"));
  EXPECT_THROW(peeler.render(peeled(request("smart", {}))), std::invalid_argument);
}
