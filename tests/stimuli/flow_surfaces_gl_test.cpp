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

// Seed 004 Fig. 7: from the walkthrough's first-person start, `dynamic` with its defaults shows
// objects through the walls — the picture differs from `opaque` — and `targets=role` (only the
// unique trophy) does not reveal the other objects.
TEST(Walkthrough, DynamicShowsObjectsThroughTheWallsByDefault) {
  render::Renderer renderer(render::loadScene("builtin:walkthrough", allSceneSpecs()));
  render::RenderRequest request;
  request.width = request.height = 96;
  const auto renderStyle = [&](const std::string& style, std::map<std::string, std::string> settings) {
    request.style = style;
    request.settings = std::move(settings);
    return renderer.render(request);
  };
  const core::Image opaque = renderStyle("opaque", {}), dynamic = renderStyle("dynamic", {});
  const core::Image roleOnly = renderStyle("dynamic", {{"targets", "role"}});
  const auto differing = [&](const core::Image& a) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
      const glm::vec4 d = glm::abs(a.pixels[i] - opaque.pixels[i]);
      n += std::max({d.r, d.g, d.b}) > 0.1f ? 1 : 0;  // more than the two fills' rounding
    }
    return n;
  };
  EXPECT_GT(differing(dynamic), 200u);
  EXPECT_GT(differing(dynamic), 4 * differing(roleOnly));
}

}  // namespace
}  // namespace tlab::stimuli
