// lighting=pbr (seed 002 Sec. 4.2: Disney BRDF for direct light, image-based lighting for
// indirect light): a grey sphere seen from the front shows the studio rig — the GGX highlight
// of the key light up and to the left, the procedural sky's blue above and its warm ground below
// — in every style that takes the common `lighting` key.
#include <string>
#include <vector>

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

// The fills that shade (slots, scatter, list) and the raster pass compile the frame's lighting
// model in (withLighting) rather than reading it from a uniform (issue #29): each still draws the
// model of its frame, and one renderer switches models from frame to frame.
namespace {

// A stack of 12 grey quads seen head-on: the first frame's 8 slots overflow, so it fills by the
// scatter pass.
std::vector<SceneObject> greyQuads() {
  std::vector<SceneObject> quads;
  for (int i = 0; i < 12; ++i) {
    SceneObject quad{"quad" + std::to_string(i), makeQuad({0, 0, -0.1f * float(i)}, {1.2f, 0, 0}, {0, 1.2f, 0})};
    quad.frontColor = quad.backColor = {0.5f, 0.5f, 0.5f, 1};
    quads.push_back(quad);
  }
  return quads;
}

tlab::core::Image lit(Renderer& renderer, const std::string& style, FillMethod fill, const std::string& lighting) {
  RenderRequest r;
  r.width = r.height = kSize;
  r.style = style;
  r.fill = fill;
  r.settings = {{"lighting", lighting}};
  return renderer.render(r);
}

bool sameImage(const tlab::core::Image& a, const tlab::core::Image& b) { return a.pixels == b.pixels; }

}  // namespace

TEST(PhysicalShading, EveryShadingFillAndTheRasterPassDrawTheFramesModel) {
  struct Case {
    const char* what;
    const char* style;
    FillMethod fill;
    bool quads;
  };
  for (const Case& c : {Case{"raster pass", "opaque", FillMethod::CountScatter, false},
                        Case{"blended raster pass", "unsorted", FillMethod::CountScatter, false},
                        Case{"slot fill", "constant", FillMethod::CountScatter, false},
                        Case{"list fill", "constant", FillMethod::LinkedList, false},
                        Case{"scatter fill", "constant", FillMethod::CountScatter, true}}) {
    SceneObject sphere{"sphere", makeUvSphere(1.5f, 64, 32)};
    sphere.frontColor = sphere.backColor = {0.5f, 0.5f, 0.5f, 1};
    const auto objects = c.quads ? greyQuads() : std::vector<SceneObject>{sphere};
    // A fresh renderer per model: each first frame of the quads overflows its slots.
    Renderer flatRenderer(tlab::testing::frontViewScene(objects, {0, 0, 0, 1}));
    Renderer pbrRenderer(tlab::testing::frontViewScene(objects, {0, 0, 0, 1}));
    const tlab::core::Image flat = lit(flatRenderer, c.style, c.fill, "none");
    const tlab::core::Image pbr = lit(pbrRenderer, c.style, c.fill, "pbr");
    const glm::vec4 f = flat.at(kSize / 2, kSize / 2 - 8), p = pbr.at(kSize / 2, kSize / 2 - 8);
    EXPECT_GT(f.r, 0.0f) << c.what;  // covered
    EXPECT_EQ(f.r, f.g) << c.what;   // unlit grey
    EXPECT_EQ(f.r, f.b) << c.what;
    EXPECT_GT(p.b, p.r + 0.01f) << c.what;  // the sky's blue
  }
}

TEST(PhysicalShading, OneRendererSwitchesModelsBetweenFrames) {
  SceneObject sphere{"sphere", makeUvSphere(1.5f, 64, 32)};
  sphere.frontColor = sphere.backColor = {0.5f, 0.5f, 0.5f, 1};
  for (const char* style : {"opaque", "constant", "smart", "curvature"}) {
    Renderer renderer(tlab::testing::frontViewScene({sphere}, {0, 0, 0, 1}));
    const tlab::core::Image before = lit(renderer, style, FillMethod::CountScatter, "none");
    const tlab::core::Image pbr = lit(renderer, style, FillMethod::CountScatter, "pbr");
    const tlab::core::Image head = lit(renderer, style, FillMethod::CountScatter, "headlight");
    const tlab::core::Image after = lit(renderer, style, FillMethod::CountScatter, "none");
    EXPECT_TRUE(sameImage(before, after)) << style;
    EXPECT_FALSE(sameImage(before, pbr)) << style;
    EXPECT_FALSE(sameImage(pbr, head)) << style;
    EXPECT_FALSE(sameImage(head, after)) << style;
  }
}

TEST(PhysicalShading, IsTheCurvatureStylesDefault) {
  EXPECT_TRUE(findStyle("curvature").resolve({}).is("lighting", "pbr"));  // Murray Sec. 4.2
  EXPECT_TRUE(findStyle("constant").resolve({}).is("lighting", "headlight"));
}
