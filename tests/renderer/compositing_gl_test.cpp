// Front-to-back compositing against closed forms, and the opaque style.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <tuple>

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

// The raster styles keep their colour/depth targets and read-back buffer across frames and read
// back only the scene's footprint (issue #29's GPU table). Through size changes, and with the scene
// off-centre in a wide image (the footprint away from every edge), each frame of one renderer
// shows, without lighting, an object's colour exactly where constant's picture of the same view
// (another renderer) is covered, and the background, alpha 1, everywhere else.
TEST(Compositing, RasterStylesKeepTheirTargetsAndReadTheFootprintExactly) {
  const Scene scene = loadScene("builtin:nested-spheres?n=2");
  Renderer kept(scene), reference(scene);
  Camera offCentre;
  offCentre.eye = {0.9f, -0.4f, 6.0f};
  offCentre.target = {0.9f, -0.4f, 0.0f};
  const glm::vec4 background(glm::vec3(scene.background), 1.0f);
  const auto anObjectsColour = [&](const glm::vec4& c) {
    for (const auto& o : scene.objects)
      if (glm::vec3(c) == glm::vec3(o.frontColor)) return true;
    return false;
  };
  for (const auto& [w, h, camera] : {std::tuple{33, 33, std::optional<Camera>{}}, std::tuple{61, 23, std::optional{offCentre}},
                                     std::tuple{20, 41, std::optional<Camera>{}}, std::tuple{61, 23, std::optional{offCentre}}}) {
    RenderRequest r;
    r.width = w, r.height = h, r.camera = camera;
    r.settings = {{"lighting", "none"}};
    r.style = "opaque";
    const tlab::core::Image opaque = kept.render(r);
    r.style = "unsorted";
    r.settings["alpha"] = "1";
    const tlab::core::Image unsorted = kept.render(r);
    r.style = "constant";
    const tlab::core::Image constant = reference.render(r);
    std::size_t covered = 0;
    for (std::size_t p = 0; p < constant.pixels.size(); ++p) {
      if (constant.pixels[p] == background) {
        ASSERT_EQ(opaque.pixels[p], background) << w << "x" << h << " pixel " << p;
        ASSERT_EQ(unsorted.pixels[p], background) << w << "x" << h << " pixel " << p;
      } else {
        ++covered;
        ASSERT_TRUE(anObjectsColour(opaque.pixels[p])) << w << "x" << h << " pixel " << p;
        ASSERT_NE(unsorted.pixels[p], background) << w << "x" << h << " pixel " << p;  // (a surface's blend)
      }
    }
    EXPECT_GT(covered, 0u) << w << "x" << h;
    EXPECT_LT(covered, constant.pixels.size()) << w << "x" << h;
  }
}
