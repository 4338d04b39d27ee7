// Smart transparency (Carnecky Secs. 4.4-5.5): neighbour links, boundary conditions, fields,
// compositing — against analytic or hand-computed expectations. The solve is tested in
// smart_diffusion_gl_test.cpp, the connect pass's search and the image edge in smart_connect_gl_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <cmath>
#include <functional>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/compose/smart_compositor.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/ops/connect_pass.hpp"
#include "renderer/ops/diffusion_solver.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/smart_style.hpp"
#include "tests/renderer/smart_rig.hpp"
#include "tests/support/gl_fixture.hpp"
#include "tests/support/scoped_env.hpp"

using namespace tlab::render;
using namespace tlab::testing;

TEST(NeighborLinks, FlatQuadInteriorFragmentsHaveFourMutualNeighbours) {
  SmartRig rig(loadScene("builtin:quad-stack?n=1"), 40, 30);
  const auto links = rig.fields->readLinks();
  ASSERT_EQ(links.size(), 40u * 30u);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const auto f = rig.fragment(x, y, 0);
      const bool border = x == 0 || y == 0 || x == 39 || y == 29;
      for (int k = 0; k < 4; ++k) {
        if (links[f][k] == kNone) {
          EXPECT_TRUE(border) << x << "," << y << " direction " << k;
          continue;
        }
        EXPECT_EQ(links[links[f][k]][k ^ 1], f) << "not mutual at " << x << "," << y;
      }
      if (!border) {
        // -x, +x, -y, +y in that order.
        EXPECT_EQ(links[f][0], rig.fragment(x - 1, y, 0));
        EXPECT_EQ(links[f][1], rig.fragment(x + 1, y, 0));
        EXPECT_EQ(links[f][2], rig.fragment(x, y - 1, 0));
        EXPECT_EQ(links[f][3], rig.fragment(x, y + 1, 0));
      }
    }
}

// Carnecky Fig. 2: fragments without 4 neighbours lie on the silhouettes (n·v = 0) and rims of
// the two open cylinders, computed here from the geometry and projected.
TEST(NeighborLinks, OpenCylindersLackNeighboursExactlyOnSilhouettesAndRims) {
  const int w = 96, h = 96;
  SmartRig rig(loadScene("builtin:open-cylinders?segments=256"), w, h);
  const glm::mat4 viewProj = rig.camera.projection(1.0f) * rig.camera.view();
  std::vector<char> nearCurve(std::size_t(w) * h, 0);
  const auto mark = [&](glm::vec3 p) {
    const glm::vec4 c = viewProj * glm::vec4(p, 1);
    const float x = (c.x / c.w * 0.5f + 0.5f) * w, y = (c.y / c.w * 0.5f + 0.5f) * h;  // GL window coords
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int px = int(std::floor(x)) + dx, py = int(std::floor(y)) + dy;
        if (px >= 0 && py >= 0 && px < w && py < h) nearCurve[std::size_t(py) * w + px] = 1;
      }
  };
  const glm::vec3 eye = rig.camera.eye;
  for (const auto& [radius, height] : {std::pair{1.0f, 2.0f}, std::pair{0.55f, 2.8f}}) {
    for (int i = 0; i < 2000; ++i) {  // rims
      const float phi = 2 * std::numbers::pi_v<float> * i / 2000;
      for (float y : {-height / 2, height / 2}) mark({radius * std::cos(phi), y, -radius * std::sin(phi)});
    }
    // Side silhouettes: n·(p − eye) = r − (eye.x cos φ − eye.z sin φ) = 0.
    const float a = std::hypot(eye.x, eye.z), phase = std::atan2(-eye.z, eye.x);
    for (float sign : {1.0f, -1.0f}) {
      const float phi = phase + sign * std::acos(radius / a);
      for (int i = 0; i <= 400; ++i)
        mark({radius * std::cos(phi), -height / 2 + height * i / 400.0f, -radius * std::sin(phi)});
    }
  }
  const auto links = rig.fields->readLinks();
  std::size_t lacking = 0;
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const std::size_t p = std::size_t(y) * w + x;
      for (std::uint32_t l = 0; l < rig.counts[p]; ++l) {
        const auto f = rig.heads[p] + l;
        int found = 0;
        for (int k = 0; k < 4; ++k) found += links[f][k] != kNone;
        if (found < 4) {
          ++lacking;
          EXPECT_TRUE(nearCurve[p]) << "fragment without 4 neighbours away from any silhouette at " << x << "," << y;
        }
      }
    }
  EXPECT_GT(lacking, 200u);  // the silhouettes and rims are found at all
}

TEST(BoundaryConditions, CrossSectionLikeFig8) {
  SmartRig rig(occluderScene(), 64, 16, {{"iterations", "0"}});
  const auto beta = rig.fields->read(Field::Beta), gamma = rig.fields->read(Field::Gamma);
  const auto flags = rig.fields->readFlags();
  const int y = 8;
  const auto front = rig.fragment(31, y, 0), backUnder = rig.fragment(31, y, 1), backBeside = rig.fragment(32, y, 0);
  // Red: the occluder's own boundary has fewer than 4 neighbours → β = 1, b_β = 0.
  EXPECT_EQ(beta[front], 1.0f);
  EXPECT_EQ(flags[front] & 2u, 0u);
  // Green: directly under the silhouette (layer 1, its neighbour is layer 0) → β = 0, b_β = 0.
  EXPECT_EQ(beta[backUnder], 0.0f);
  EXPECT_EQ(flags[backUnder] & 2u, 0u);
  EXPECT_EQ(gamma[backUnder], 0.0f);
  // Blue: beside the occluding edge (layer 0, its neighbour is layer 1) → γ = 1, b_γ = 0.
  EXPECT_EQ(gamma[backBeside], 1.0f);
  EXPECT_EQ(flags[backBeside] & 4u, 0u);
  // Gray: an ordinary fragment keeps the initial values and is free.
  const auto ordinary = rig.fragment(48, y, 0);
  EXPECT_EQ(beta[ordinary], 0.0f);
  EXPECT_EQ(gamma[ordinary], 0.0f);
  EXPECT_EQ(flags[ordinary], 7u);
}

// Alg. 3 with each profile modifier (none, Eq. 10, Eq. 11) evaluated on the host from the fields
// and colours, against the GPU image (the occluder's edge gives β = 1 and γ = 1 beside fragments
// at 0, so both the formula and the exact 0 of a fragment at 0 are seen).
TEST(SmartCompositing, MatchesAlgorithm3OnHandComputedListsForEveryModifier) {
  const std::map<std::string, std::function<double(double)>> modifiers = {
      {"none", [](double u) { return u; }},
      {"exp", [](double u) { return (std::exp(-3 * (1 - u)) - std::exp(-3.0)) / (1 - std::exp(-3.0)); }},  // Eq. 10, p = 3
      {"pow", [](double u) { return std::pow(u, 3.0); }}};                                                  // Eq. 11, p = 3
  for (const auto& [name, modify] : modifiers) {
    SCOPED_TRACE(name);
    const std::map<std::string, std::string> settings = {
        {"iterations", "3"}, {"lighting", "none"}, {"modifier", name}, {"p", "3"}, {"s", "0.4"}};
    SmartRig rig(occluderScene(), 64, 16, settings);
    DiffusionSolver(rig.shaders, rig.smart).solve(*rig.fields);
    const auto alpha = rig.fields->read(Field::Alpha), beta = rig.fields->read(Field::Beta),
               gamma = rig.fields->read(Field::Gamma);
    Renderer renderer(occluderScene());
    RenderRequest r;
    r.width = 64;
    r.height = 16;
    r.style = "smart";
    r.settings = settings;
    const tlab::core::Image img = renderer.render(r);
    const glm::vec3 bg = rig.scene.background;
    int seenZero = 0, seenOne = 0;
    for (int x : {30, 31, 32, 33, 40}) {
      const int glY = 8;
      const std::size_t p = std::size_t(glY) * 64 + x;
      glm::dvec3 c(0);
      double T = 1;
      for (std::uint32_t l = 0; l < rig.counts[p]; ++l) {
        const auto f = rig.heads[p] + l;
        seenZero += beta[f] == 0.0f ? 1 : 0;
        seenOne += beta[f] == 1.0f || gamma[f] == 1.0f ? 1 : 0;
        const glm::dvec3 ci = glm::dvec3(l == 0 && x < 32 ? rig.scene.objects[1].frontColor : rig.scene.objects[0].frontColor);
        const double aHat = (1 - modify(gamma[f])) * (alpha[f] + (1 - alpha[f]) * modify(beta[f]));
        c += T * aHat * ci;
        T *= 1 - aHat;
      }
      c += T * glm::dvec3(bg);
      const glm::vec4 got = img.at(x, 16 - 1 - glY);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], c[k], 1.0 / 255.0 + 1e-6) << "x " << x << " channel " << k;
    }
    EXPECT_GT(seenZero, 0);
    EXPECT_GT(seenOne, 0);
  }
}

// Eq. 5 solves Eq. 6: n layers of α = 1 − (1 − s)^(1/n) accumulate exactly s.
class AdaptiveAlpha : public ::testing::TestWithParam<int> {};
TEST_P(AdaptiveAlpha, AccumulatesExactlyS) {
  const int n = GetParam();
  const Scene scene = loadScene("builtin:quad-stack?m=1&n=" + std::to_string(n));
  Renderer renderer(scene);
  RenderRequest r;
  r.width = 12;
  r.height = 10;
  r.style = "smart";
  r.settings = {{"iterations", "0"}, {"alpha_init", "adaptive"}, {"s", "0.6"}, {"halos", "off"},
                {"silhouettes", "off"}, {"lighting", "none"}};
  const tlab::core::Image img = renderer.render(r);
  // Fragment colours are stored as RGBA8: the layer colour is the quantised one.
  const glm::vec3 layer = glm::round(glm::vec3(scene.objects[0].frontColor) * 255.0f) / 255.0f;
  const glm::vec3 expected = 0.6f * layer + 0.4f * glm::vec3(scene.background);
  for (const auto& px : img.pixels)
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(px[k], expected[k], 2e-5);
}
INSTANTIATE_TEST_SUITE_P(Layers, AdaptiveAlpha, ::testing::Values(1, 2, 3, 7, 16, 64));

// Degenerate inputs: an empty image, a pixel with one fragment, a one-pixel-wide strip, more than
// 100 layers in a pixel; every image finite and within [0, 1].
TEST(SmartTransparency, DegenerateScenesStayFinite) {
  Scene strip;
  SceneObject o;
  o.mesh = makeQuad({0, 0, 0}, {0.004f, 0, 0}, {0, 1, 0});  // ~1 pixel wide at 64 px
  strip.objects.push_back(o);
  strip.camera = Camera{};
  strip.camera->eye = {0, 0, 3};
  Scene away = loadScene("builtin:sphere");
  away.camera = Camera{};
  away.camera->eye = {0, 0, 5};
  away.camera->target = {0, 0, 10};  // looking away: no fragments at all
  away.camera->nearPlane = 0.1f;
  for (auto [scene, size] : {std::pair{strip, 64}, std::pair{away, 32}, std::pair{loadScene("builtin:quad-stack?n=120"), 8},
                             std::pair{loadScene("builtin:sphere?segments=8&rings=4"), 5}}) {
    for (const char* lambda : {"0", "1", "1000"}) {
      Renderer renderer(scene);
      RenderRequest r;
      r.width = r.height = size;
      r.style = "smart";
      r.settings = {{"lambda_alpha", lambda}, {"iterations", "5"}};
      RenderStats stats;
      const tlab::core::Image img = renderer.render(r, &stats);
      for (const auto& px : img.pixels)
        for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(px[k]) && px[k] >= 0.0f && px[k] <= 1.0f);
    }
  }
}

TEST(SmartTransparency, RunsOnlyThePassesItNeeds) {
  Renderer renderer(loadScene("builtin:sphere"));
  RenderRequest r;
  r.width = r.height = 16;
  r.style = "smart";
  RenderStats stats;
  renderer.render(r, &stats);
  std::vector<std::string> ran;
  for (const auto& p : stats.passMilliseconds) ran.push_back(p.first);
  EXPECT_EQ(ran, (std::vector<std::string>{"fill", "sort", "connect", "solve", "compose"}));
  // Initial α uniform (Eq. 4, the default): the solve only spreads β and γ, and says so; γ
  // (λγ = 0.1) settles within 10 of the 20 steps.
  ASSERT_EQ(stats.operations.size(), 3u);
  EXPECT_EQ(stats.operations[0], "solve: alpha diffusion skipped (initial alpha uniform: alpha_init=constant)");
  EXPECT_EQ(stats.operations[1].rfind("solve: beta spreading (Eq. 9 max, ", 0), 0u) << stats.operations[1];
  EXPECT_EQ(stats.operations[2].rfind("solve: gamma spreading (Eq. 9 max, ", 0), 0u) << stats.operations[2];
  EXPECT_NE(stats.operations[2].find(" of 20 steps: settled)"), std::string::npos) << stats.operations[2];
  // Nothing to solve at all: uniform α, no silhouettes, no halos.
  r.settings = {{"halos", "off"}, {"silhouettes", "off"}};
  renderer.render(r, &stats);
  ran.clear();
  for (const auto& p : stats.passMilliseconds) ran.push_back(p.first);
  EXPECT_EQ(ran, (std::vector<std::string>{"fill", "sort", "connect", "compose"}));
  EXPECT_EQ(stats.operations, (std::vector<std::string>{
                                  "connect: alpha diffusion skipped (initial alpha uniform: alpha_init=constant)",
                                  "connect: gamma skipped (halos=off)", "connect: beta skipped (silhouettes=off)"}));
  r.settings = {};
  // One connected component: no component ids in the records.
  EXPECT_EQ(stats.fragmentProperties, (std::vector<std::string>{"depth", "triangle", "color", "normal", "depth_gradient"}));
  r.settings = {{"iterations", "0"}};
  renderer.render(r, &stats);
  ran.clear();
  for (const auto& p : stats.passMilliseconds) ran.push_back(p.first);
  EXPECT_EQ(ran, (std::vector<std::string>{"fill", "sort", "connect", "compose"}));
  r.style = "constant";
  r.settings = {};
  renderer.render(r, &stats);
  // fill, compose (which sorts, issue #29): no neighbour pass; where the host passes run, a sort
  // of the colours alone between them (the twenty-eighth round)
  ran.clear();
  for (const auto& p : stats.passMilliseconds) ran.push_back(p.first);
  const std::vector<std::string> expected =
      tlab::gpu::hostPassesWanted() ? std::vector<std::string>{"fill", "sort", "compose"} : std::vector<std::string>{"fill", "compose"};
  EXPECT_EQ(ran, expected);
  // Two components (nested spheres): ids are stored so ε = ∞ across them.
  Renderer nested(loadScene("builtin:nested-spheres?n=2"));
  r.style = "smart";
  nested.render(r, &stats);
  EXPECT_EQ(stats.fragmentProperties.back(), "ids");
}

// RenderRequest::timeParts (tlab bench render --scene ... --parts): the passes' parts are listed
// by name under their pass — the solve's frontier steps as one part where they run as host code
// (TLAB_HOST_PASSES=on, llvmpipe's default), as many parts as the solve says it ran them where they
// run as the shader (off) — each part within its pass's time; and the picture is the one an
// untimed frame gives, either way.
TEST(SmartTransparency, TimingThePassesPartsLeavesThePictureAsItWas) {
  const ScopedEnv hostCode("TLAB_HOST_PASSES", "on");  // (as by default on llvmpipe; the shader's below)
  Renderer renderer(loadScene("builtin:nested-spheres?n=2"));
  RenderRequest r;
  r.width = 48;
  r.height = 40;
  r.style = "smart";
  RenderStats plain, timed;
  const auto without = renderer.render(r, &plain);
  EXPECT_TRUE(plain.parts.empty());
  r.timeParts = true;
  const auto with = renderer.render(r, &timed);
  EXPECT_TRUE(with.pixels == without.pixels);
  std::map<std::string, int> counts;
  for (const auto& p : timed.parts) counts[p.name] = p.count;
  // The second frame fills straight into slots as long as the first frame's lists.
  for (const char* name : {"fill rasterization into slots", "fill prefix sum", "connect phase 1 on the host", "connect phase 2 on the host",
                           "solve beta frontier on the host", "compose blend on the host"})
    EXPECT_TRUE(counts.count(name)) << name;
  EXPECT_EQ(counts.count("compose read-back"), 0u);
  EXPECT_EQ(counts["connect phase 1 on the host"], 1);
  EXPECT_EQ(counts.count("connect phase 1"), 0u);
  EXPECT_EQ(counts["solve beta frontier on the host"], 1);
  const std::string beta = timed.operations.at(1);  // "solve: beta spreading (Eq. 9 max, K[ of N] steps...)"
  const std::string after = "solve: beta spreading (Eq. 9 max, ";
  ASSERT_EQ(beta.rfind(after, 0), 0u) << beta;
  {  // the steps as the shader: one part each
    const ScopedEnv shaders("TLAB_HOST_PASSES", "off");
    Renderer onTheGl(loadScene("builtin:nested-spheres?n=2"));
    RenderStats steps;
    EXPECT_TRUE(onTheGl.render(r, &steps).pixels == without.pixels);
    std::map<std::string, int> stepCounts;
    for (const auto& p : steps.parts) stepCounts[p.name] = p.count;
    EXPECT_EQ(stepCounts["solve beta frontier step"], std::stoi(beta.substr(after.size()))) << beta;
    EXPECT_EQ(stepCounts.count("solve beta frontier on the host"), 0u);
    EXPECT_EQ(stepCounts["connect phase 1"], 1);
    EXPECT_EQ(stepCounts.count("connect phase 1 on the host"), 0u);
    EXPECT_EQ(stepCounts["connect phase 2"], 1);
    EXPECT_EQ(stepCounts.count("connect phase 2 on the host"), 0u);
    EXPECT_EQ(stepCounts["compose read-back"], 1);
    EXPECT_EQ(stepCounts.count("compose blend on the host"), 0u);
    EXPECT_EQ(steps.operations, timed.operations);
  }
  for (const auto& [pass, ms] : timed.passMilliseconds) {
    double inside = 0;
    for (const auto& p : timed.parts)
      if (p.name.rfind(pass + " ", 0) == 0) inside += p.ms;
    EXPECT_LE(inside, ms + 1e-9) << pass;
  }
  for (const auto& p : timed.parts) {
    const std::string pass = p.name.substr(0, p.name.find(' '));
    EXPECT_TRUE(std::any_of(timed.passMilliseconds.begin(), timed.passMilliseconds.end(),
                            [&](const auto& q) { return q.first == pass; }))
        << p.name;
  }
}

// The passes with a host-code twin (the fill's prefix sum, the sort, the connect pass's phase 2,
// the solve's frontier steps, constant's and smart's blends: the default where the GL runs on the CPU) and their shaders
// (TLAB_HOST_PASSES=off) draw the same pictures, bit for bit: smart transparency with silhouettes
// and halos, adaptive α, halos off and Eq. 8 spreading, the other buffer styles; lists that fit the
// slots, lists that outgrow them (the scatter fill, then slots), and two frames of each renderer.
TEST(SmartTransparency, HostPassesAndTheirShadersDrawTheSamePictures) {
  struct Case {
    const char* source;
    const char* style;
    std::map<std::string, std::string> settings;
  };
  const std::vector<Case> cases = {
      {"builtin:torus", "smart", {}},
      {"builtin:nested-spheres?n=6", "smart", {{"lambda_gamma", "0.3"}}},
      {"builtin:open-cylinders", "smart", {{"alpha_init", "adaptive"}, {"iterations", "5"}}},
      {"builtin:nested-spheres?n=3", "smart", {{"halos", "off"}}},
      {"builtin:nested-spheres?n=6", "smart", {{"spread", "diffusion"}}},
      // The blend as host code (issue #29, twenty-eighth round) with each profile modifier: Eq. 11,
      // none, and Eq. 10 (the default) with halos whose γ spreads.
      {"builtin:nested-spheres?n=6", "smart", {{"modifier", "pow"}, {"p", "2.5"}}},
      {"builtin:torus", "smart", {{"modifier", "none"}, {"alpha_init", "adaptive"}}},
      {"builtin:quad-stack?n=6&m=3", "smart", {{"modifier", "pow"}}},
      {"builtin:nested-spheres?n=6", "iris", {}},
      {"builtin:torus", "constant", {}},
      {"builtin:open-cylinders", "view-dependent", {}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c.source) + " " + c.style + " " + std::to_string(c.settings.size()) + " settings");
    RenderRequest r;
    r.width = 64;
    r.height = 56;
    r.style = c.style;
    r.settings = c.settings;
    std::vector<tlab::core::Image> pictures[2];
    for (const bool onHost : {true, false}) {
      const ScopedEnv passes("TLAB_HOST_PASSES", onHost ? "on" : "off");
      Renderer renderer(loadScene(c.source));
      for (int frame = 0; frame < 2; ++frame) pictures[onHost ? 0 : 1].push_back(renderer.render(r));
    }
    for (int frame = 0; frame < 2; ++frame) {
      EXPECT_TRUE(pictures[0][frame].pixels == pictures[1][frame].pixels) << "frame " << frame;
      EXPECT_TRUE(pictures[0][frame].pixels == pictures[0][0].pixels) << "frame " << frame;
    }
  }
}

TEST(SmartTransparency, HalosOffAllocatesNoGammaField) {
  SmartRig rig(occluderScene(), 16, 8, {{"halos", "off"}});
  EXPECT_FALSE(rig.fields->hasGamma());
  EXPECT_TRUE(rig.fields->hasBeta());
  EXPECT_THROW(rig.fields->read(Field::Gamma), std::logic_error);
}

// The compose leaves out a field the connect pass listed no seed for (issue #29): that is only
// right where the field is 0 at every fragment, and it must not be claimed where one is above 0.
TEST(SmartTransparency, FieldsWithoutSeedsAreKnownToBeZero) {
  struct Case {
    const char* name;
    Scene scene;
    bool betaZero, gammaZero;
  };
  // A stack seen straight on whose quads cover the view: no silhouette and no occluding edge. The
  // occluder's front edge: silhouettes (β) and a halo (γ) on the quad behind it.
  const Case cases[] = {{"quad-stack", loadScene("builtin:quad-stack?n=3"), true, true},
                        {"occluder", occluderScene(), false, false}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    SmartRig rig(c.scene, 40, 30);
    ASSERT_TRUE(rig.fields->seedsListed());
    for (auto [field, zero] : {std::pair{Field::Beta, c.betaZero}, std::pair{Field::Gamma, c.gammaZero}}) {
      EXPECT_EQ(rig.fields->allZero(field), zero);
      const auto values = rig.fields->read(field);
      const bool allValuesZero = std::all_of(values.begin(), values.end(), [](float v) { return v == 0.0f; });
      EXPECT_EQ(allValuesZero, zero);
    }
  }
  // Without seed lists (the Eq. 8 spreading reads every fragment) nothing is claimed.
  SmartRig spreading(loadScene("builtin:quad-stack?n=3"), 40, 30, {{"spread", "diffusion"}});
  EXPECT_FALSE(spreading.fields->allZero(Field::Beta));
}

// The connect pass stores only the fields that vary (issue #29): Eq. 4's α is s at every fragment
// and a listed field without a seed is 0, so neither is written for each fragment; a listed field
// with seeds is 0 but 1 at its seeds, over whatever its buffer held. read() gives those values
// without writing a buffer, and a pass that binds such a field finds it written out first.
TEST(SmartTransparency, TheConnectPassStoresOnlyTheFieldsThatVary) {
  const std::uint32_t garbage = 0x7FC0DEADu;  // a NaN
  const auto fill = [&](const tlab::gpu::Buffer& b) {
    glClearNamedBufferData(b.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &garbage);
  };
  const auto words = [](const tlab::gpu::Buffer& b, std::size_t n) {
    std::vector<std::uint32_t> v(n);
    b.download(v.data(), n * 4);
    return v;
  };
  for (const char* source : {"builtin:quad-stack?n=3", "occluder"}) {
    SCOPED_TRACE(source);
    SmartRig rig(std::string(source) == "occluder" ? occluderScene() : loadScene(source), 40, 30);
    TransparencyFields& fields = *rig.fields;
    const std::size_t n = fields.fragments();
    const bool seeded = std::string(source) == "occluder";
    const auto fresh = std::map<Field, std::vector<float>>{
        {Field::Beta, fields.read(Field::Beta)}, {Field::Gamma, fields.read(Field::Gamma)}};
    // Every copy of every field full of garbage, then the pass again over the same buffers.
    std::map<Field, std::array<const tlab::gpu::Buffer*, 2>> copies;
    for (Field f : {Field::Alpha, Field::Beta, Field::Gamma}) {
      copies[f] = {&fields.current(f), &fields.output(f)};
      for (const auto* b : copies[f]) fill(*b);
    }
    connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, fields);
    ASSERT_EQ(fields.uniformValue(Field::Alpha), std::optional<float>(float(rig.smart.s)));
    EXPECT_EQ(fields.read(Field::Alpha), std::vector<float>(n, float(rig.smart.s)));
    for (Field f : {Field::Beta, Field::Gamma}) {
      EXPECT_EQ(fields.uniformValue(f).has_value(), !seeded) << int(f);
      EXPECT_EQ(fields.read(f), fresh.at(f)) << int(f);
      EXPECT_EQ(std::count(fresh.at(f).begin(), fresh.at(f).end(), 1.0f) > 0, seeded) << int(f);
    }
    // α was not written: both its copies still hold the garbage (and read() wrote neither).
    for (const auto* b : copies[Field::Alpha]) EXPECT_EQ(words(*b, n), std::vector<std::uint32_t>(n, garbage));
    // A pass that binds the fields finds each one written out: α = s, β and γ as read.
    fields.bindCurrent();
    for (Field f : {Field::Alpha, Field::Beta, Field::Gamma}) {
      EXPECT_FALSE(fields.uniformValue(f).has_value()) << int(f);
      std::vector<float> stored(n);
      fields.current(f).download(stored.data(), n * 4);
      EXPECT_EQ(stored, f == Field::Alpha ? std::vector<float>(n, float(rig.smart.s)) : fresh.at(f)) << int(f);
    }
  }
  // Eq. 5's α varies with the list's length: stored for each fragment.
  SmartRig adaptive(occluderScene(), 40, 30, {{"alpha_init", "adaptive"}});
  EXPECT_FALSE(adaptive.fields->uniformValue(Field::Alpha).has_value());
  const auto alpha = adaptive.fields->read(Field::Alpha);
  EXPECT_NE(std::count(alpha.begin(), alpha.end(), alpha.front()), std::ptrdiff_t(alpha.size()));
}
