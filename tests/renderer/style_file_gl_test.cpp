// Style files rendered by the Renderer beside the built-in styles: examples/styles/constant.glsl
// against the built-in `constant`, the depth-tinted alpha against its definition layer by layer,
// and a broken style's compiler error mapped to the user's line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

namespace {

const std::string kExamples = std::string(TLAB_SOURCE_DIR) + "/examples/styles/";

tlab::core::Image renderWith(Renderer& renderer, const std::string& style, std::map<std::string, std::string> settings,
                             RenderStats* stats = nullptr) {
  RenderRequest r;
  r.width = 96;
  r.height = 72;
  r.style = style;
  r.settings = std::move(settings);
  return renderer.render(r, stats);
}

std::string writeStyle(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("tlab_style_gl_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path.string();
}

std::string renderError(const std::string& path) {
  Renderer renderer(loadScene("builtin:sphere"));
  try {
    renderWith(renderer, path, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(rendered)";
}

const std::string kHeader = R"(/* tlab style
name = "broken"
description = "a style with a mistake"
properties = ["color"]
[[parameter]]
name = "alpha"
type = "float"
default = 0.5
range = [0.0, 1.0]
description = "opacity"
*/
)";  // 11 lines

}  // namespace

class ConstantFile : public ::testing::TestWithParam<std::tuple<std::string, std::string, std::string>> {};

// The issue's bar: the file written as a researcher would write it equals the built-in within 1/255.
TEST_P(ConstantFile, EqualsTheBuiltInConstantWithinOneStep) {
  const auto& [scene, alpha, lighting] = GetParam();
  Renderer renderer(loadScene(scene));
  const std::map<std::string, std::string> settings = {{"alpha", alpha}, {"lighting", lighting}};
  const auto builtin = renderWith(renderer, "constant", settings);
  const auto file = renderWith(renderer, kExamples + "constant.glsl", settings);
  const auto a = tlab::core::toRgba8(builtin), b = tlab::core::toRgba8(file);
  ASSERT_EQ(a.size(), b.size());
  int worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  float worstFloat = 0;
  for (std::size_t p = 0; p < builtin.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) worstFloat = std::max(worstFloat, std::abs(builtin.pixels[p][c] - file.pixels[p][c]));
  std::cout << "constant.glsl vs constant on " << scene << " alpha=" << alpha << " lighting=" << lighting
            << ": max difference " << worst << "/255 (float " << worstFloat << ")\n";
  EXPECT_LE(worst, 1);
  EXPECT_LE(worstFloat, 1.0f / 255.0f);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ConstantFile,
                         ::testing::Values(std::make_tuple("builtin:torus", "0.25", "headlight"),
                                           std::make_tuple("builtin:nested-spheres?n=3", "0.6", "headlight"),
                                           std::make_tuple("builtin:quad-stack?n=7", "0.3", "none")));

// Each layer's opacity is alpha_near + (alpha_far − alpha_near)·d with d its depth between the
// near and far planes: checked at one pixel against the depths the buffer holds there.
TEST(StyleFileGl, DepthTintedAlphaGrowsWithEachLayersDepth) {
  const Scene scene = loadScene("builtin:quad-stack?n=5");
  Renderer renderer(scene);
  RenderStats stats;
  const auto image = renderWith(renderer, kExamples + "depth_tinted_alpha.glsl",
                                {{"alpha_near", "0.05"}, {"alpha_far", "0.9"}, {"tint", "0"}, {"lighting", "none"}}, &stats);
  const auto layers = renderer.fragmentsAt(48, 36);
  ASSERT_EQ(layers.size(), 5u);
  const float n = stats.camera.nearPlane, f = stats.camera.farPlane;
  glm::vec3 c(0.0f);
  float T = 1.0f;
  for (const auto& layer : layers) {
    const float d = std::clamp((layer.depth - n) / (f - n), 0.0f, 1.0f);
    const float a = 0.05f + (0.9f - 0.05f) * d;
    c += T * a * glm::vec3(scene.objects[0].frontColor);
    T *= 1.0f - a;
  }
  c += T * glm::vec3(scene.background);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(image.at(48, 36)[k], c[k], 1.0 / 255.0);
  // and it is not the constant style: the far layers weigh more than a uniform 0.05 would give
  EXPECT_GT(std::abs(image.at(48, 36)[0] - renderWith(renderer, "constant", {{"alpha", "0.05"}, {"lighting", "none"}}).at(48, 36)[0]),
            0.05f);
}

TEST(StyleFileGl, ACompileErrorNamesTheUsersFileAndLine) {
  const std::string path = writeStyle("typo.glsl", kHeader + R"(vec4 composite() {
  vec3 c = vec3(0.0);
  for (int i = 0; i < fragmentCount(); ++i)
    c += alpah * fragment(i).color.rgb;
  return vec4(c, 1.0);
}
)");
  const std::string error = renderError(path);
  EXPECT_EQ(error.rfind(path + ":15: ", 0), 0u) << error;
  EXPECT_NE(error.find("alpah"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(StyleFileGl, AnUndeclaredPropertyIsACompileErrorOnItsLine) {
  const std::string path = writeStyle("normal.glsl", kHeader + R"(vec4 composite() {
  if (fragmentCount() == 0) return background();
  return vec4(fragment(0).normal, 1.0);
}
)");
  const std::string error = renderError(path);
  EXPECT_EQ(error.rfind(path + ":14: ", 0), 0u) << error;
}

TEST(StyleFileGl, AFileWithoutCompositeIsRefusedNamingTheFile) {
  const std::string path = writeStyle("empty.glsl", kHeader + "float unused() { return alpha; }\n");
  const std::string error = renderError(path);
  EXPECT_EQ(error.rfind(path + ":", 0), 0u) << error;
  EXPECT_NE(error.find("composite"), std::string::npos) << error;
}

// The per-fragment stage over Carnecky Alg. 2 links: with no iterations every fragment keeps
// its initial value 0 and silhouette_halo.glsl is `constant` exactly; with iterations the halo is
// 1 on the silhouette, spreads inward by `decay` per link, and leaves the centre untouched.
TEST(StyleFileGl, TheHaloStageSpreadsFromSilhouettesAlongTheLinks) {
  Renderer renderer(loadScene("builtin:sphere"));
  const std::map<std::string, std::string> base = {{"alpha", "0.3"}, {"lighting", "none"}};
  const auto constant = renderWith(renderer, "constant", base);
  auto none = base;
  none["iterations"] = "0";
  const auto still = renderWith(renderer, kExamples + "silhouette_halo.glsl", none);
  float worst = 0;
  for (std::size_t p = 0; p < constant.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(constant.pixels[p][c] - still.pixels[p][c]));
  EXPECT_LE(worst, 1.0f / 255.0f);

  auto halo = base;
  halo["iterations"] = "12";
  halo["decay"] = "0.25";
  halo["strength"] = "1";
  RenderStats stats;
  const auto image = renderWith(renderer, kExamples + "silhouette_halo.glsl", halo, &stats);
  std::vector<std::string> passes;  // the fill's passes, then the stage, then the compositor
  for (const auto& [name, ms] : stats.passMilliseconds) passes.push_back(name);
  ASSERT_GE(passes.size(), 2u);
  EXPECT_EQ(passes[passes.size() - 2], "links+iterate");
  EXPECT_EQ(passes.back(), "compose");
  // The centre is more than 1/decay = 4 links from the silhouette: as constant.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(48, 36)[c], constant.at(48, 36)[c], 1.0 / 255.0);
  // Along the middle row, the first covered pixel from the left is on the silhouette: both the
  // front and the back fragment there have value 1, so the pixel is nearly black (strength 1).
  int edge = 0;
  const auto counts = renderer.layerCounts();
  while (edge < 96 && counts[std::size_t(36) * 96 + edge] == 0) ++edge;
  ASSERT_LT(edge, 48);
  EXPECT_LT(image.at(edge, 36).r, 0.1f) << "silhouette pixel " << edge;
  EXPECT_LT(image.at(edge, 36).r, constant.at(edge, 36).r - 0.2f);
  // Six pixels in (> 4 links), the halo has faded out again.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(edge + 6, 36)[c], constant.at(edge + 6, 36)[c], 1.0 / 255.0);
}
