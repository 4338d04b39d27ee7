// Carnecky's complex surfaces must be complex: at least 6 layers at some pixel from their default
// view, counted by the illustration buffer after a `constant` render.
#include <gtest/gtest.h>

#include <algorithm>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "stimuli/scenes/stimulus_scenes.hpp"
#include "tests/support/gl_fixture.hpp"

namespace tlab::stimuli {
namespace {

std::uint16_t maxLayers(const std::string& source) {
  render::Renderer renderer(render::loadScene(source, allSceneSpecs()));
  render::RenderRequest request;
  request.width = request.height = 512;
  request.style = "constant";
  renderer.render(request);
  const auto counts = renderer.layerCounts();
  return *std::max_element(counts.begin(), counts.end());
}

TEST(FlowSurfaces, PretzelBubbleAndToroidReachSixLayersFromTheirDefaultView) {
  for (const char* name : {"builtin:pretzel", "builtin:bubble", "builtin:toroid"}) EXPECT_GE(maxLayers(name), 6) << name;
}

}  // namespace
}  // namespace tlab::stimuli
