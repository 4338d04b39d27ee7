// The IRIS effects one at a time on a front-facing quad (window, two-sided colouring, stripe
// modulation, LIC), context geometry, the IRIS look's defaults, and the illustration buffer and
// depth peeling agreeing on all of them. Closed forms: iris_styles_gl_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/renderer/iris_probe.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::testing;

namespace {

// One quad filling the view: white in front, black behind, on a black background.
tlab::core::Image renderQuad(std::map<std::string, std::string> settings, bool flip = false) {
  Scene s = stretchedQuad({1.0f, 1.0f});
  if (flip) {
    s.objects[0].mesh = makeQuad({0, 0, 0}, {0, 2, 0}, {2, 0, 0});  // wound away from the viewer
  }
  s.objects[0].backColor = {0.2f, 0.4f, 0.6f, 1};
  return renderOneEffect(s, "iris", 64, std::move(settings));
}

}  // namespace

// IRIS Sec. 3.3: inside the window the opacity is scaled by window_opacity, outside not at all,
// with a smooth fall-off in between.
TEST(IrisWindow, ScalesOpacityInsideTheWindowOnly) {
  const tlab::core::Image img = renderQuad({{"opacity", "constant"}, {"alpha", "0.8"}, {"window_layers", "1"}, {"window_x", "0.25"},
                                {"window_y", "0.25"}, {"window_radius", "0.1"}, {"window_falloff", "0.1"},
                                {"window_opacity", "0.25"}});
  EXPECT_NEAR(img.at(16, 16).r, 0.8f * 0.25f, 1e-3);  // the centre, (0.25, 0.25) of the image
  EXPECT_NEAR(img.at(60, 60).r, 0.8f, 1e-3);          // far outside
  const float between = img.at(16 + 10, 16).r;        // 10 px out: radius 6.4, fall-off to 12.8
  EXPECT_GT(between, 0.2f + 1e-3);
  EXPECT_LT(between, 0.8f - 1e-3);
}

TEST(IrisTwoSided, BackFacesUseTheBackColourOnlyWhenTwoSided) {
  const tlab::core::Image twoSided = renderQuad({{"opacity", "constant"}, {"alpha", "1"}, {"two_sided", "on"}}, true);
  const tlab::core::Image oneSided = renderQuad({{"opacity", "constant"}, {"alpha", "1"}, {"two_sided", "off"}}, true);
  EXPECT_NEAR(twoSided.at(32, 32).b, 0.6f, 1e-3);
  EXPECT_NEAR(oneSided.at(32, 32).b, 1.0f, 1e-3);
}

// IRIS Sec. 5.1: multiplicative modulation never raises the opacity above α_view, additive
// never lowers it.
TEST(IrisStripes, MultiplicativeAndAdditiveModulationBoundTheOpacity) {
  const auto range = [](const tlab::core::Image& img) {
    float lo = 1, hi = 0;
    for (int x = 0; x < 64; ++x) {
      lo = std::min(lo, img.at(x, 32).r);
      hi = std::max(hi, img.at(x, 32).r);
    }
    return std::pair{lo, hi};
  };
  std::map<std::string, std::string> s{{"opacity", "constant"}, {"alpha", "0.4"}, {"stripes", "s"},
                                       {"stripe_period", "8"},      {"stripe_strength", "0.5"}, {"stripe_darken", "0"}};
  const auto [mLo, mHi] = range(renderQuad(s));
  EXPECT_NEAR(mHi, 0.4f, 2e-3);
  EXPECT_NEAR(mLo, 0.4f * 0.5f, 2e-3);
  s["stripe_modulation"] = "add";
  const auto [aLo, aHi] = range(renderQuad(s));
  EXPECT_NEAR(aLo, 0.4f, 2e-3);
  EXPECT_NEAR(aHi, 0.9f, 2e-3);
}

// IRIS Sec. 5: context geometry (Role::Opaque) is shaded alike but always opaque, in both the
// illustration buffer and depth peeling.
TEST(IrisContext, OpaqueObjectsAreContextGeometry) {
  Scene s = alphaProbeSphere();
  s.objects[0].frontColor = s.objects[0].backColor = {0, 0, 1, 1};
  SceneObject box;
  box.mesh = makeBox(glm::vec3(0.3f));
  box.frontColor = box.backColor = {1, 0, 0, 1};
  box.roles = Role::Opaque;
  s.objects.push_back(box);
  s.background = {0, 1, 0, 1};
  RenderRequest r;
  r.width = r.height = 48;
  r.style = "iris";
  r.camera = frontCamera();
  r.settings = {{"opacity", "constant"}, {"alpha", "0.3"}, {"lighting", "none"}, {"specular", "0"}, {"silhouettes", "on"},
                {"stripes", "off"}};
  RenderRequest peeled = r;
  peeled.depthPeeling = true;
  for (const tlab::core::Image& img : {Renderer(s).render(r), Renderer(s).render(peeled)}) {
    const glm::vec4 c = img.at(24, 24);
    EXPECT_NEAR(c.r, 0.7f, 1e-3);  // the box behind one layer of α = 0.3, never the background
    EXPECT_NEAR(c.g, 0.0f, 1e-3);
    EXPECT_NEAR(c.b, 0.3f, 1e-3);
  }
}

namespace {

tlab::core::Image renderTorus(const std::string& style, const std::map<std::string, std::string>& settings, bool peel = false) {
  Scene s = buildBuiltinScene("torus?major_segments=48&minor_segments=24", builtinScenes());
  RenderRequest r;
  r.width = r.height = 96;
  r.style = style;
  r.settings = settings;
  r.depthPeeling = peel;
  return Renderer(s).render(r);
}

// (largest, mean) absolute channel difference in 1/255 units.
std::pair<int, double> channelDifference(const tlab::core::Image& a, const tlab::core::Image& b) {
  const auto x = tlab::core::toRgba8(a), y = tlab::core::toRgba8(b);
  int largest = 0;
  double sum = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const int d = std::abs(int(x[i]) - int(y[i]));
    largest = std::max(largest, d);
    sum += d;
  }
  return {largest, sum / double(x.size())};
}

}  // namespace

// `iris` alone shows the IRIS look (Figs. 1, 10): it differs visibly from `constant` and has
// dark silhouette pixels (a white-backed scene has none with `constant`).
TEST(IrisDefaults, ShowTheIrisLookNotConstantTransparency) {
  const tlab::core::Image iris = renderTorus("iris", {}), constant = renderTorus("constant", {});
  const auto [largest, mean] = channelDifference(iris, constant);
  EXPECT_GT(largest, 100);
  EXPECT_GT(mean, 5.0);
  const auto dark = [](const tlab::core::Image& img) {
    int n = 0;
    for (const auto& p : img.pixels) n += (p.r + p.g + p.b) < 0.3f ? 1 : 0;
    return n;
  };
  EXPECT_GT(dark(iris), 50);  // silhouettes
  EXPECT_EQ(dark(constant), 0);
}

// IRIS Sec. 5.1: the illustration buffer and depth peeling take the derivatives of Eqs. 2-4 the
// same way (dFdx/dFdy at rasterization), so every IRIS effect agrees between the two renderers:
// at most 2/255 in any channel, 0.05/255 on average (normals are stored in 2 × 16 bits in the
// buffer, as floats by peeling).
TEST(IrisRenderers, BufferAndPeelingAgreeWithDerivativesAndStripes) {
  for (const auto& settings : std::vector<std::map<std::string, std::string>>{
           {}, {{"stripes", "both"}, {"stripe_modulation", "add"}}, {{"stripes", "lic"}, {"shading", "gooch"}}}) {
    const auto [largest, mean] = channelDifference(renderTorus("iris", settings), renderTorus("iris", settings, true));
    EXPECT_LE(largest, 2) << settings.size();
    EXPECT_LE(mean, 0.05) << settings.size();
  }
}

// IRIS Fig. 10c: the LIC-like pattern is noise blurred along t — along t it changes slowly, across
// s quickly (on a front-facing quad with s to the right and t upwards).
TEST(IrisStripes, LicNoiseIsBlurredAlongT) {
  Renderer renderer(stretchedQuad({1.0f, 1.0f}));
  RenderRequest r;
  r.width = r.height = 128;
  r.style = "iris";
  r.camera = frontCamera();
  r.settings = patternSettings("lic", 32);
  r.settings["silhouettes"] = "off";
  const tlab::core::Image img = renderer.render(r);
  double alongS = 0, alongT = 0;
  for (int y = 32; y < 96; ++y)
    for (int x = 32; x < 96; ++x) {
      alongS += std::abs(img.at(x + 1, y).r - img.at(x, y).r);
      alongT += std::abs(img.at(x, y + 1).r - img.at(x, y).r);
    }
  EXPECT_GT(alongS, 4.0 * alongT);
  EXPECT_GT(alongT, 0.0);
}
