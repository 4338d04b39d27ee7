// Small golden images (tests/data/golden/*.png, 64x64) of each IRIS and Diepstraten style, and of
// depth peeling, compared with a tolerance: at most 1% of the channels may differ by more than
// 6/255 (llvmpipe versions differ in the last bits of rasterization). TLAB_UPDATE_GOLDEN=1
// rewrites the files instead.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/scene/technical_scenes.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

namespace {

struct GoldenCase {
  const char* name;
  const char* scene;
  const char* style;
  std::map<std::string, std::string> settings;
  bool peel = false;
};

std::vector<GoldenCase> cases() {
  return {
      {"angle_torus", "builtin:torus?major_segments=64&minor_segments=32", "angle", {{"shading", "phong"}}},
      {"normal_variation_torus", "builtin:torus?major_segments=64&minor_segments=32", "normal-variation", {{"gamma", "0.4"}}},
      {"iris_stripes_silhouettes_torus", "builtin:torus?major_segments=64&minor_segments=32", "iris",
       {{"opacity", "angle"}, {"stripes", "s"}, {"stripe_period", "6"}, {"silhouettes", "on"}, {"shading", "gooch"}}},
      {"iris_window_nested", "builtin:nested-spheres?n=2", "iris",
       {{"opacity", "constant"}, {"alpha", "0.5"}, {"window_layers", "1"}, {"window_radius", "0.2"}, {"stripes", "off"},
        {"silhouettes", "off"}}},
      {"angle_peeled_torus", "builtin:torus?major_segments=64&minor_segments=32", "angle",
       {{"shading", "phong"}, {"silhouettes", "on"}}, true},
      {"view_dependent_mug_box", "builtin:mug-box?segments=48", "view-dependent", {}},
      {"view_dependent_crank", "builtin:crank-cylinder?segments=32", "view-dependent", {{"boundaries", "implicit"}}},
  };
}

tlab::core::Image renderCase(const GoldenCase& c) {
  std::vector<BuiltinSceneSpec> catalog = builtinScenes();
  for (const auto& s : technicalScenes()) catalog.push_back(s);
  RenderRequest r;
  r.width = r.height = 64;
  r.style = c.style;
  r.settings = c.settings;
  r.depthPeeling = c.peel;
  return Renderer(loadScene(c.scene, catalog)).render(r);
}

}  // namespace

class GoldenImage : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenImage, MatchesWithinTolerance) {
  const GoldenCase& c = GetParam();
  const std::string path = std::string(TLAB_TEST_DATA) + "/golden/" + c.name + ".png";
  const auto rgba = tlab::core::toRgba8(renderCase(c));
  if (std::getenv("TLAB_UPDATE_GOLDEN")) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    tlab::core::Image img(64, 64);
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
      img.pixels[i] = glm::vec4(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]) / 255.0f;
    tlab::core::writeFileAtomically(path, tlab::core::encodePng(img));
    GTEST_SKIP() << "rewrote " << path;
  }
  int w = 0, h = 0, n = 0;
  unsigned char* golden = stbi_load(path.c_str(), &w, &h, &n, 4);
  ASSERT_NE(golden, nullptr) << "missing " << path << " (TLAB_UPDATE_GOLDEN=1 writes it)";
  ASSERT_EQ(w, 64);
  ASSERT_EQ(h, 64);
  int off = 0, worst = 0;
  for (std::size_t i = 0; i < rgba.size(); ++i) {
    const int d = std::abs(int(rgba[i]) - int(golden[i]));
    worst = std::max(worst, d);
    off += d > 6;
  }
  stbi_image_free(golden);
  EXPECT_LE(off, int(rgba.size() / 100)) << c.name << ": worst difference " << worst << "/255";
}

INSTANTIATE_TEST_SUITE_P(Styles, GoldenImage, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) { return std::string(info.param.name); });
