// Dynamic transparency (Elmqvist et al., seed 004) end to end. Colours are flat (lighting=none)
// and chosen so each channel tells one story: the target is pure red, distractors have no red,
// so a pixel's red channel is exactly the weight of the target in it.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/ops/alpha_mask.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/styles/dynamic_style.hpp"
#include "tests/support/front_view_scene.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

namespace {

constexpr int kSize = 64;
constexpr float kAlphaT = 0.4f, kAlpha0 = 0.2f;
constexpr int kBorder = 4;
const glm::vec4 kRed{1, 0, 0, 1}, kBoxColor{0, 0.5f, 1, 1};
const float kBehindThree = std::pow(1.0f - kAlphaT, 3.0f);  // the target's weight behind three boxes

SceneObject box(const std::string& name, float half, glm::vec3 centre, glm::vec4 color, Role roles) {
  SceneObject o;
  o.name = name;
  o.mesh = makeBox(glm::vec3(half));
  transformMesh(o.mesh, glm::translate(glm::mat4(1.0f), centre));
  o.frontColor = o.backColor = color;
  o.roles = roles;
  return o;
}

SceneObject wall(glm::vec4 color, Role roles) {
  SceneObject o;
  o.name = "wall";
  o.mesh = makeQuad({0, 0, 2}, {3, 0, 0}, {0, 3, 0});
  o.frontColor = o.backColor = color;
  o.roles = roles;
  return o;
}

Scene sceneOf(std::vector<SceneObject> objects, glm::vec4 background = {0, 1, 0, 1}) {
  return tlab::testing::frontViewScene(std::move(objects), background);
}

// A red target inside three nested opaque boxes, one group drawn innermost first (Sec. V.2).
Scene nestedBoxes() {
  std::vector<SceneObject> o = {box("target", 0.3f, glm::vec3(0), kRed, Role::Target)};
  for (float half : {0.6f, 0.9f, 1.2f}) o.push_back(box("box", half, glm::vec3(0), kBoxColor, Role::Distractor));
  for (auto& object : o) object.group = 0;
  return sceneOf(std::move(o));
}

tlab::core::Image render(const Scene& scene, std::map<std::string, std::string> settings = {}) {
  Renderer renderer(scene);
  RenderRequest r;
  r.width = r.height = kSize;
  r.style = "dynamic";
  r.settings = {{"lighting", "none"}, {"alpha_target", std::to_string(kAlphaT)}, {"alpha_0", std::to_string(kAlpha0)},
                {"border", std::to_string(kBorder)}, {"mask_size", std::to_string(kSize)}};
  for (const auto& [k, v] : settings) r.settings[k] = v;
  return renderer.render(r);
}

// The 4 x 4 pixels around the image centre (all on the target's silhouette).
template <typename F>
void forCentre(F&& f) {
  for (int y = kSize / 2 - 2; y < kSize / 2 + 2; ++y)
    for (int x = kSize / 2 - 2; x < kSize / 2 + 2; ++x) f(x, y);
}

}  // namespace

TEST(DynamicTransparency, DefaultStackingIsThePapersPerOccluderMask) {
  // Three occluding front faces, each blended with α_T (seed 004 Sec. V.3): the target keeps
  // (1 − α_T)^3 by default.
  const tlab::core::Image img = render(nestedBoxes());
  forCentre([&](int x, int y) { EXPECT_NEAR(img.at(x, y).r, kBehindThree, 2e-3f) << x << "," << y; });
}

TEST(DynamicTransparency, SharedStackingKeepsWeightOneMinusAlphaTAtAnyDepth) {
  const tlab::core::Image img = render(nestedBoxes(), {{"stacking", "shared"}});
  forCentre([&](int x, int y) { EXPECT_NEAR(img.at(x, y).r, 1.0f - kAlphaT, 2e-3f) << x << "," << y; });
}

TEST(DynamicTransparency, OpaqueStyleHidesTheTarget) {
  Renderer renderer(nestedBoxes());
  RenderRequest r;
  r.width = r.height = kSize;
  r.style = "opaque";
  r.settings = {{"lighting", "none"}};
  const tlab::core::Image img = renderer.render(r);
  forCentre([&](int x, int y) { EXPECT_EQ(img.at(x, y).r, 0.0f); });
}

TEST(DynamicTransparency, ImpenetrableWallHidesTheTarget) {
  const glm::vec4 blue{0, 0, 1, 1};
  const tlab::core::Image hidden = render(sceneOf({box("target", 0.3f, glm::vec3(0), kRed, Role::Target), wall(blue, Role::Impenetrable)}));
  forCentre([&](int x, int y) {
    EXPECT_EQ(hidden.at(x, y).r, 0.0f);
    EXPECT_EQ(hidden.at(x, y).b, 1.0f);  // never made transparent
  });
  const tlab::core::Image seen = render(sceneOf({box("target", 0.3f, glm::vec3(0), kRed, Role::Target), wall(blue, Role::Distractor)}));
  forCentre([&](int x, int y) { EXPECT_NEAR(seen.at(x, y).r, 1.0f - kAlphaT, 2e-3f); });
}

TEST(DynamicTransparency, TargetIsNotSeeThroughToItself) {
  // One target object of two boxes one behind the other; its back faces are blue.
  SceneObject target = box("target", 0.3f, glm::vec3(0, 0, 0.8f), kRed, Role::Target);
  SceneObject back = box("back", 0.5f, glm::vec3(0, 0, -0.8f), kRed, Role::Target);
  appendMesh(target.mesh, back.mesh);
  target.backColor = {0, 0, 1, 1};
  const tlab::core::Image self = render(sceneOf({target}));
  forCentre([&](int x, int y) { EXPECT_EQ(self.at(x, y), kRed); });
  // Control: the same boxes as two targets — the front one is see-through onto the back one.
  SceneObject front = box("front", 0.3f, glm::vec3(0, 0, 0.8f), kRed, Role::Target);
  SceneObject behind = box("behind", 0.5f, glm::vec3(0, 0, -0.8f), {0, 0, 1, 1}, Role::Target);
  const tlab::core::Image two = render(sceneOf({front, behind}));
  forCentre([&](int x, int y) {
    EXPECT_NEAR(two.at(x, y).r, kAlphaT, 2e-3f);
    EXPECT_NEAR(two.at(x, y).b, 1.0f - kAlphaT, 2e-3f);
  });
}

TEST(DynamicTransparency, BorderGradientRisesMonotonicallyOverNPixels) {
  // A black distractor wall in front of a small target on a white background: a pixel's green
  // channel is 1 − the wall's opacity there. With one mask cell per pixel the border layers are
  // whole pixels: layer i has α_B(i) (Alg. 2 line 8), then the wall is opaque.
  const tlab::core::Image img = render(sceneOf({box("target", 0.3f, glm::vec3(0), kRed, Role::Target), wall({0, 0, 0, 1}, Role::Distractor)},
                                   {1, 1, 1, 1}));
  const int y = kSize / 2;
  int edge = kSize / 2;
  while (edge < kSize && img.at(edge, y).g == 0.0f) ++edge;  // target pixels have no green
  ASSERT_GT(edge, kSize / 2);
  ASSERT_LT(edge + kBorder, kSize);
  EXPECT_NEAR(img.at(edge - 1, y).r, 1.0f - kAlphaT, 2e-3f);
  float previous = 1.0f;
  for (int i = 1; i <= kBorder; ++i) {
    const float opacity = 1.0f - img.at(edge + i - 1, y).g;
    EXPECT_NEAR(opacity, borderAlpha(i, kBorder, kAlpha0), 2e-3f) << "layer " << i;
    EXPECT_LT(1.0f - opacity, previous);
    previous = 1.0f - opacity;
  }
  EXPECT_EQ(img.at(edge + kBorder, y).g, 0.0f);  // beyond n pixels the wall is opaque
}

TEST(DynamicTransparency, ActiveModeUncoversOnlyInsideTheLens) {
  std::map<std::string, std::string> away, over;
  setDynamicLens(away, {0.1f, 0.1f}, 0.1f);
  setDynamicLens(over, {0.5f, 0.5f}, 0.2f);
  const tlab::core::Image outside = render(nestedBoxes(), away), inside = render(nestedBoxes(), over);
  forCentre([&](int x, int y) {
    EXPECT_EQ(outside.at(x, y).r, 0.0f);
    EXPECT_NEAR(inside.at(x, y).r, kBehindThree, 2e-3f);
  });
}

TEST(DynamicTransparency, LayerControlLimitsTheLayersUncovered) {
  const tlab::core::Image two = render(nestedBoxes(), {{"max_layers", "2"}}), three = render(nestedBoxes(), {{"max_layers", "3"}});
  forCentre([&](int x, int y) {
    EXPECT_EQ(two.at(x, y).r, 0.0f);  // three boxes in front: not uncovered with L = 2
    EXPECT_NEAR(three.at(x, y).r, kBehindThree, 2e-3f);
  });
}

TEST(DynamicTransparency, CircleAndEllipseMasksUncoverTheTarget) {
  for (const char* shape : {"circle", "ellipse"}) {
    const tlab::core::Image img = render(nestedBoxes(), {{"mask", shape}});
    forCentre([&](int x, int y) { EXPECT_NEAR(img.at(x, y).r, kBehindThree, 2e-3f) << shape; });
  }
}

// The mask at the image's resolution (mask_size=0, the default) hugs the target's outline: every
// pixel next to the target's pixels is in border layer 1 (α_0), wherever it lies — no cells of
// the paper's 128² grid, which are 1.5 pixels wide at 192² (3 × 3-pixel blocks at 384²).
TEST(DynamicTransparency, DefaultMaskFollowsTheOutlineAtPixelResolution) {
  constexpr int size = 192;
  SceneObject target;
  target.name = "target";
  target.mesh = makeUvSphere(0.35f, 48, 24);
  target.frontColor = target.backColor = kRed;
  target.roles = Role::Target;
  Renderer renderer(sceneOf({target, wall({0, 0, 0, 1}, Role::Distractor)}, {1, 1, 1, 1}));
  RenderRequest r;
  r.width = r.height = size;
  r.style = "dynamic";
  r.settings = {{"lighting", "none"}, {"alpha_0", std::to_string(kAlpha0)}};
  const tlab::core::Image img = renderer.render(r);
  const auto onTarget = [&](int x, int y) { return img.at(x, y).r > 0.0f && img.at(x, y).g == 0.0f; };
  int ring = 0;
  for (int y = 1; y < size - 1; ++y)
    for (int x = 1; x < size - 1; ++x) {
      if (onTarget(x, y)) continue;
      bool touches = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) touches = touches || onTarget(x + dx, y + dy);
      if (!touches) continue;
      ++ring;
      EXPECT_NEAR(1.0f - img.at(x, y).g, kAlpha0, 2e-3f) << x << "," << y;  // the wall's opacity: α_B(1)
    }
  EXPECT_GT(ring, 100);
}
