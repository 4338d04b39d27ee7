// A live view (an interactive trial's scene rendered from the participant's camera, in `tlab run`
// and the online turntable) takes a style file as it takes a built-in style: each frame equals the
// Renderer's picture in the style file from the navigator's camera, before and after an orbit.
#include <gtest/gtest.h>

#include <memory>

#include "renderer/params/style_params.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "stimuli/scenes/stimulus_scenes.hpp"
#include "study/run/live_view.hpp"
#include "study/run/stimulus_library.hpp"
#include "tests/support/gl_fixture.hpp"

namespace tlab::study {
namespace {

const std::string kStyleFile = std::string(TLAB_SOURCE_DIR) + "/examples/styles/depth_tinted_alpha.glsl";

std::vector<std::uint8_t> pictureOf(render::Renderer& renderer, const render::Camera& camera, const std::string& style,
                                    const std::vector<std::string>& settings) {
  render::RenderRequest request;
  request.width = request.height = 96;
  request.style = style;
  for (const auto& s : settings) render::addSetting(request.settings, s);
  request.camera = camera;
  request.timePasses = false;
  return Canvas(renderer.render(request)).rgba();
}

TEST(LiveViewStyleFile, FramesAreTheStyleFilesPictureFromTheNavigatorsCamera) {
  auto scene = std::make_shared<const render::Scene>(render::loadScene("builtin:abstract?seed=3", stimuli::allSceneSpecs()));
  StimulusKey key;
  key.scene = "builtin:abstract?seed=3";
  key.style = kStyleFile;
  key.renderSettings = {"alpha_far=0.7"};
  key.width = key.height = 96;
  const render::Camera start = stimulusCamera(*scene, key);
  LiveView view(scene, key, Navigation::Orbit, start);
  render::Renderer renderer(*scene);
  const auto first = view.frame().rgba();
  EXPECT_EQ(first, pictureOf(renderer, start, kStyleFile, key.renderSettings));
  EXPECT_NE(first, pictureOf(renderer, start, "constant", {})) << "the style file made no difference";
  view.navigator().drag(60.0, 0.0);  // the participant orbits
  const render::Camera moved = view.navigator().camera();
  const auto second = view.frame().rgba();
  EXPECT_NE(second, first);
  EXPECT_EQ(second, pictureOf(renderer, moved, kStyleFile, key.renderSettings));
}

}  // namespace
}  // namespace tlab::study
