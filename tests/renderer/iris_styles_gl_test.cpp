// The IRIS local styles against closed forms: angle-based (Sec. 3.1) and normal-variation
// (Eq. 2) opacity on a sphere, and the image-space period of adaptive stripes (Eqs. 3-5) under
// anisotropic stretching of (s, t) (Fig. 6) and under perspective (Fig. 5).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <map>
#include <optional>
#include <string>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "tests/renderer/iris_probe.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::testing;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 96;

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
  return renderOneEffect(alphaProbeSphere(), style, kSize, std::move(settings));
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

// The modes IRIS's shaders branch on (opacity, shading, stripes, silhouettes) are compiled into
// their programs (IllustrativeSettings::defines, issue #29): one renderer that changes them from
// frame to frame draws each frame's own, through the buffer and through depth peeling.
TEST(IrisModes, OneRendererSwitchesModesBetweenFrames) {
  using tlab::render::RenderRequest;
  for (const bool peel : {false, true}) {
    tlab::render::Renderer renderer(
        tlab::render::buildBuiltinScene("torus", tlab::render::builtinScenes()));
    const auto frame = [&](std::map<std::string, std::string> settings) {
      RenderRequest r;
      r.width = r.height = 64;
      r.style = "iris";
      r.depthPeeling = peel;
      r.settings = std::move(settings);
      return renderer.render(r).pixels;
    };
    const std::map<std::string, std::string> first = {{"shading", "phong"}, {"stripes", "s"}, {"silhouettes", "on"}};
    const auto before = frame(first);
    const auto other = frame({{"opacity", "angle"}, {"shading", "gooch"}, {"stripes", "t"}, {"silhouettes", "off"}});
    const auto flat = frame({{"opacity", "constant"}, {"lighting", "none"}, {"stripes", "both"}, {"silhouettes", "on"}});
    const auto after = frame(first);
    EXPECT_EQ(before, after) << (peel ? "peeling" : "buffer");
    EXPECT_NE(before, other) << (peel ? "peeling" : "buffer");
    EXPECT_NE(other, flat) << (peel ? "peeling" : "buffer");
    EXPECT_NE(flat, after) << (peel ? "peeling" : "buffer");
  }
}
