// Front-to-back compositing against closed forms, and the opaque style.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

class ConstantClosedForm : public ::testing::TestWithParam<std::tuple<int, double>> {};

// n equal layers of opacity a over a background: c = (1 − (1 − a)^n)·c_layer + (1 − a)^n·c_bg.
TEST_P(ConstantClosedForm, MatchesWithinOneStep) {
  const auto [n, a] = GetParam();
  const Scene scene = loadScene("builtin:quad-stack?m=1&n=" + std::to_string(n));
  Renderer renderer(scene);
  RenderRequest r;
  r.width = 40;
  r.height = 30;
  r.style = "constant";
  r.settings = {{"alpha", std::to_string(a)}, {"lighting", "none"}};
  const tlab::core::Image img = renderer.render(r);
  const glm::vec3 layer = scene.objects[0].frontColor, bg = scene.background;
  const double t = std::pow(1.0 - a, n);
  const auto rgba = tlab::core::toRgba8(img);
  for (int c = 0; c < 3; ++c) {
    const double expected = (1.0 - t) * layer[c] + t * bg[c];
    for (std::size_t p = 0; p < img.pixels.size(); ++p) {
      ASSERT_NEAR(img.pixels[p][c], expected, 1.0 / 255.0) << "pixel " << p << " channel " << c;
      ASSERT_NEAR(rgba[p * 4 + c] / 255.0, expected, 1.0 / 255.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Layers, ConstantClosedForm,
                         ::testing::Combine(::testing::Values(1, 2, 7, 32), ::testing::Values(0.1, 0.5, 0.9)));

TEST(Compositing, OpaqueShowsTheNearestSurfaceAndTheBackground) {
  const Scene scene = loadScene("builtin:nested-spheres?n=2");
  Renderer renderer(scene);
  RenderRequest r;
  r.width = 33;
  r.height = 33;
  r.style = "opaque";
  r.settings = {{"lighting", "none"}};
  const tlab::core::Image img = renderer.render(r);
  EXPECT_NEAR(img.at(16, 16).r, scene.objects[0].frontColor.r, 1e-6);  // outer shell in front
  EXPECT_NEAR(img.at(0, 0).r, scene.background.r, 1e-6);
}

TEST(Compositing, HeadlightShadingIsBrightestFacingTheViewer) {
  Renderer renderer(loadScene("builtin:sphere"));
  RenderRequest r;
  r.width = 65;
  r.height = 65;
  r.style = "opaque";
  const tlab::core::Image img = renderer.render(r);
  EXPECT_GT(img.at(32, 32).r, img.at(32, 8).r);
}
