// The IRIS local styles against closed forms: angle-based (Sec. 3.1) and normal-variation
// (Eq. 2) opacity on a sphere, and the image-space period of adaptive stripes (Eqs. 3-5) under
// anisotropic stretching of (s, t) (Fig. 6) and under perspective (Fig. 5).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <optional>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 96;

// A unit sphere, white in front and black behind, on black: the image is the front layer's α.
Scene alphaProbeSphere() {
  Scene s;
  SceneObject o;
  o.name = "sphere";
  o.mesh = makeUvSphere(1.0f, 192, 96);
  o.frontColor = {1, 1, 1, 1};
  o.backColor = {0, 0, 0, 1};
  s.objects.push_back(o);
  s.background = {0, 0, 0, 1};
  return s;
}

Camera frontCamera() {
  Camera c;
  c.eye = {0, 0, 3};
  c.target = {0, 0, 0};
  c.fovyDegrees = 45.0f;
  c.nearPlane = 1.0f;
  c.farPlane = 5.0f;
  return c;
}

// The view-space unit normal where the ray through pixel centre (x, y) (row 0 = top) first hits
// the unit sphere 3 units in front of the eye; nothing when it misses.
std::optional<glm::dvec3> sphereNormalAt(double x, double y, int size) {
  const double t = std::tan(22.5 * kPi / 180.0);
  const glm::dvec3 d = glm::normalize(glm::dvec3(((x + 0.5) / size * 2 - 1) * t, (1 - (y + 0.5) / size * 2) * t, -1));
  const glm::dvec3 c(0, 0, -3);
  const double b = glm::dot(d, c), disc = b * b - (glm::dot(c, c) - 1.0);
  if (disc < 0) return std::nullopt;
  return glm::dvec3((b - std::sqrt(disc)) * d - c);
}

tlab::core::Image renderProbe(const std::string& style, std::map<std::string, std::string> settings) {
  Renderer renderer(alphaProbeSphere());
  RenderRequest r;
  r.width = r.height = kSize;
  r.style = style;
  r.camera = frontCamera();
  settings["lighting"] = "none";
  settings["specular"] = "0";
  settings.emplace("stripes", "off");      // `iris` defaults to the IRIS look (stripes,
  settings.emplace("silhouettes", "off");  // silhouettes); these tests look at one effect each
  r.settings = settings;
  return renderer.render(r);
}

}  // namespace

TEST(IrisAngle, MatchesTheClosedFormOnASphere) {
  const double aMin = 0.1, aMax = 0.9;
  const tlab::core::Image img = renderProbe("angle", {{"alpha_min", "0.1"}, {"alpha_max", "0.9"}});
  int checked = 0;
  for (int y = 4; y < kSize; y += 7)
    for (int x = 3; x < kSize; x += 5) {
      const auto n = sphereNormalAt(x, y, kSize);
      if (!n) continue;
      const glm::dvec3 p = *n + glm::dvec3(0, 0, -3);
      const double cosine = std::abs(glm::dot(*n, glm::normalize(-p)));
      if (cosine < 0.15) continue;  // the last pixel ring mixes tessellation and coverage
      const double a = 2.0 / kPi * std::acos(cosine);  // IRIS Sec. 3.1
      EXPECT_NEAR(img.at(x, y).r, (1 - a) * aMin + a * aMax, 0.02) << "pixel " << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

TEST(IrisNormalVariation, MatchesTheClosedFormOnASphere) {
  const double aMin = 0.05, aMax = 0.95, gamma = 0.5;
  const tlab::core::Image img = renderProbe("normal-variation", {{"alpha_min", "0.05"}, {"alpha_max", "0.95"}, {"gamma", "0.5"}});
  int checked = 0;
  for (int y = 4; y < kSize; y += 7)
    for (int x = 3; x < kSize; x += 5) {
      const auto n = sphereNormalAt(x, y, kSize);
      const auto nl = sphereNormalAt(x - 1, y, kSize), nr = sphereNormalAt(x + 1, y, kSize);
      const auto nu = sphereNormalAt(x, y - 1, kSize), nd = sphereNormalAt(x, y + 1, kSize);
      if (!n || !nl || !nr || !nu || !nd || n->z < 0.3) continue;
      // IRIS Eq. 2 with central differences of the exact n_z, clamped before γ.
      const double gi = 0.5 * (nr->z - nl->z), gj = 0.5 * (nu->z - nd->z);
      const double a = std::pow(std::min(1.0, std::sqrt(gi * gi + gj * gj)), gamma);
      EXPECT_NEAR(img.at(x, y).r, (1 - a) * aMin + a * aMax, 0.04) << "pixel " << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 60);
  // Normal variation grows towards the silhouette: more opaque at the rim than at the centre.
  EXPECT_GT(img.at(kSize / 2, 10).r, img.at(kSize / 2, kSize / 2).r + 0.1);
}

namespace {

// The dominant period (in samples) of a signal: the strongest non-zero DFT frequency.
double dominantPeriod(const std::vector<double>& v) {
  const std::size_t n = v.size();
  double mean = 0;
  for (double x : v) mean += x / double(n);
  double best = 0;
  std::size_t bestK = 1;
  for (std::size_t k = 1; k <= n / 2; ++k) {
    std::complex<double> sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += (v[i] - mean) * std::polar(1.0, -2.0 * kPi * double(k * i) / double(n));
    if (std::abs(sum) > best) {
      best = std::abs(sum);
      bestK = k;
    }
  }
  return double(n) / double(bestK);
}

// A white quad on black whose image is the stripe pattern itself (α = c(s, t) of Eq. 5).
std::map<std::string, std::string> patternSettings(const std::string& axis, double period) {
  return {{"opacity", "constant"}, {"alpha", "1"},           {"stripes", axis},      {"stripe_period", std::to_string(period)},
          {"stripe_strength", "1"}, {"stripe_darken", "0"}, {"lighting", "none"},  {"specular", "0"}};
}

Scene stretchedQuad(glm::vec2 stScale) {
  Scene s;
  SceneObject o;
  o.mesh = makeQuad({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
  for (auto& st : o.mesh.st) st *= stScale;
  o.frontColor = o.backColor = {1, 1, 1, 1};
  s.objects.push_back(o);
  s.background = {0, 0, 0, 1};
  return s;
}

}  // namespace

class StripeStretch : public ::testing::TestWithParam<std::tuple<float, float, const char*>> {};

// IRIS Fig. 6: 1000x anisotropic stretching of (s, t) leaves the image-space period within a
// factor 2 of the requested one, in both directions and with both axes striped.
TEST_P(StripeStretch, PeriodStaysWithinAFactorTwo) {
  const auto [ss, ts, axis] = GetParam();
  const double period = 12.0;
  Renderer renderer(stretchedQuad({ss, ts}));
  RenderRequest r;
  r.width = r.height = 128;
  r.style = "iris";
  r.camera = frontCamera();
  r.settings = patternSettings(axis, period);
  const tlab::core::Image img = renderer.render(r);
  const bool alongS = std::string(axis) != "t";
  std::vector<double> line;
  for (int i = 0; i < 128; ++i) line.push_back(alongS ? img.at(i, 64).r : img.at(64, i).r);
  const double measured = dominantPeriod(line);
  EXPECT_GE(measured, period / 2) << "axis " << axis;
  EXPECT_LE(measured, period * 2) << "axis " << axis;
}

INSTANTIATE_TEST_SUITE_P(Stretch, StripeStretch,
                         ::testing::Values(std::make_tuple(1000.0f, 1.0f, "s"), std::make_tuple(1.0f, 1000.0f, "t"),
                                           std::make_tuple(0.001f, 1.0f, "s"), std::make_tuple(1000.0f, 1.0f, "both")));

// IRIS Fig. 5: a ground plane seen at a grazing angle; t runs away from the viewer, so a plain
// texture's stripes would shrink many-fold towards the horizon. The adaptive period stays within
// a factor 2 of the request both near and far.
TEST(StripePerspective, PeriodStaysWithinAFactorTwoNearAndFar) {
  Scene s;
  SceneObject o;
  o.mesh = makeQuad({0, 0, -20}, {4, 0, 0}, {0, 0, -20});  // the plane y = 0 from z = 0 to z = -40
  for (auto& st : o.mesh.st) st.y *= 50.0f;
  o.frontColor = o.backColor = {1, 1, 1, 1};
  s.objects.push_back(o);
  s.background = {0, 0, 0, 1};
  Camera c;
  c.eye = {0, 0.6f, 1.0f};
  c.target = {0, 0, -6};
  c.fovyDegrees = 60.0f;
  c.nearPlane = 0.1f;
  c.farPlane = 60.0f;
  Renderer renderer(s);
  RenderRequest r;
  r.width = r.height = 256;
  r.style = "iris";
  r.camera = c;
  const double period = 8.0;
  r.settings = patternSettings("t", period);
  const tlab::core::Image img = renderer.render(r);
  // Find the horizon (first covered row from the top), then measure far and near windows.
  int top = 0;
  while (top < 256 && img.at(128, top).r == 0.0f && img.at(129, top).r == 0.0f && img.at(130, top).r == 0.0f) ++top;
  ASSERT_LT(top, 150);
  for (int first : {top + 24, 256 - 72}) {
    std::vector<double> column;
    for (int y = first; y < first + 64; ++y) column.push_back(img.at(128, y).r);
    const double measured = dominantPeriod(column);
    EXPECT_GE(measured, period / 2) << "window from row " << first;
    EXPECT_LE(measured, period * 2) << "window from row " << first;
  }
}

namespace {

// One quad filling the view: white in front, black behind, on a black background.
tlab::core::Image renderQuad(std::map<std::string, std::string> settings, bool flip = false) {
  Scene s = stretchedQuad({1.0f, 1.0f});
  if (flip) {
    s.objects[0].mesh = makeQuad({0, 0, 0}, {0, 2, 0}, {2, 0, 0});  // wound away from the viewer
  }
  s.objects[0].backColor = {0.2f, 0.4f, 0.6f, 1};
  Renderer renderer(s);
  RenderRequest r;
  r.width = r.height = 64;
  r.style = "iris";
  r.camera = frontCamera();
  settings["lighting"] = "none";
  settings["specular"] = "0";
  settings.emplace("stripes", "off");      // `iris` defaults to the IRIS look (stripes,
  settings.emplace("silhouettes", "off");  // silhouettes); these tests look at one effect each
  r.settings = settings;
  return renderer.render(r);
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
