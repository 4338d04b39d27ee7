// lighting=pbr (seed 002 Sec. 4.2: Disney BRDF for direct light, image-based lighting for
// indirect light): a grey sphere seen from the front shows the studio rig — the GGX highlight
// of the key light up and to the left, the procedural sky's blue above and its warm ground below
// — in every style that takes the common `lighting` key.
#include <gtest/gtest.h>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/styles/style.hpp"
#include "tests/support/front_view_scene.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

namespace {

constexpr int kSize = 64;

tlab::core::Image greySphere(const std::string& style, const std::string& lighting) {
  SceneObject sphere{"sphere", makeUvSphere(1.5f, 64, 32)};
  sphere.frontColor = sphere.backColor = {0.5f, 0.5f, 0.5f, 1};
  sphere.roles = Role::Opaque;
  Renderer renderer(tlab::testing::frontViewScene({sphere}, {0, 0, 0, 1}));
  RenderRequest r;
  r.width = r.height = kSize;
  r.style = style;
  r.settings = {{"lighting", lighting}};
  if (style == "constant") r.settings["alpha"] = "1";
  if (style == "curvature") r.settings = {{"lighting", lighting}, {"mode", "plain"}, {"alpha", "1"}};
  return renderer.render(r);
}

}  // namespace

TEST(PhysicalShading, KeyLightAndSkyShowOnAGreySphere) {
  const tlab::core::Image img = greySphere("opaque", "pbr");
  const glm::vec4 top = img.at(kSize / 2, 14), bottom = img.at(kSize / 2, kSize - 15);
  EXPECT_GT(top.b - top.r, bottom.b - bottom.r + 0.05f);  // the sky's blue above, its warm ground below
  EXPECT_GT(bottom.r, bottom.b);
  int bx = 0, by = 0;
  float brightest = 0.0f;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (img.at(x, y).g > brightest) {
        brightest = img.at(x, y).g;
        bx = x;
        by = y;
      }
  EXPECT_LT(bx, kSize / 2);  // the highlight faces the key light: left …
  EXPECT_LT(by, kSize / 2);  // … and up (row 0 is the top)
  const tlab::core::Image head = greySphere("opaque", "headlight");
  EXPECT_FLOAT_EQ(head.at(kSize / 2, 14).r, head.at(kSize / 2, 14).b);  // the headlight has no colour
}

TEST(PhysicalShading, EveryStyleTakesIt) {
  for (const char* style : {"constant", "iris", "curvature"}) {
    const tlab::core::Image pbr = greySphere(style, "pbr"), head = greySphere(style, "headlight");
    const glm::vec4 top = pbr.at(kSize / 2, 14), bottom = pbr.at(kSize / 2, kSize - 15);
    EXPECT_GT(top.b - top.r, bottom.b - bottom.r + 0.02f) << style;
    EXPECT_NE(pbr.at(kSize / 2, 14), head.at(kSize / 2, 14)) << style;
  }
}

TEST(PhysicalShading, IsTheCurvatureStylesDefault) {
  EXPECT_TRUE(findStyle("curvature").resolve({}).is("lighting", "pbr"));  // Murray Sec. 4.2
  EXPECT_TRUE(findStyle("constant").resolve({}).is("lighting", "headlight"));
}
