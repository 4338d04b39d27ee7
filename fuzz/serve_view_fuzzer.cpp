// Fuzz target: arbitrary bytes as the JSON body of a live trial's view request (POST
// /api/<token>/view, issue #30) — read as the server reads it (parseViewInput) and, when accepted,
// steered into a walking and an orbiting navigator of Elmqvist's WALKTHROUGH as the GL worker
// does. Input must never crash the server nor move a camera outside the trial's bounds or to a
// number that is not finite, however many messages it sends.
// fuzz-sources: study/serve/view_input.cpp study/serve/live_frames.cpp study/run/camera_navigator.cpp
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>

#include "renderer/scene/scene_source.hpp"
#include "study/design/scene_catalog.hpp"
#include "study/serve/live_frames.hpp"
#include "study/serve/view_input.hpp"

namespace {

using nlohmann::json;
using namespace tlab::study;

void require(bool ok) {
  if (!ok) std::abort();
}

const LiveTrial& trial(Navigation navigation) {
  static const auto scene = std::make_shared<const tlab::render::Scene>(tlab::render::loadScene("builtin:walkthrough?seed=2", sceneCatalog()));
  static const LiveTrial walk{scene, {}, Navigation::Walk, *scene->camera};
  static const LiveTrial orbit{scene, {}, Navigation::Orbit, *scene->camera};
  return navigation == Navigation::Walk ? walk : orbit;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const json body = json::parse(std::string(reinterpret_cast<const char*>(data), size), nullptr, false);
  if (body.is_discarded() || !body.is_object()) return 0;  // the server refuses it before reading the input
  ViewInput input;
  try {
    input = parseViewInput(body.contains("input") ? body["input"] : json::object());
  } catch (const std::invalid_argument& e) {
    require(std::string(e.what()).size() > 0);
    return 0;
  }
  require(std::abs(input.dx) <= kMaxDragPixels && std::abs(input.dy) <= kMaxDragPixels);
  require(std::abs(input.forward) <= kMaxKeySteps && std::abs(input.turn) <= kMaxKeySteps);
  require(!input.point || (input.point->x >= 0.0f && input.point->x <= 1.0f && input.point->y >= 0.0f && input.point->y <= 1.0f));
  require(!input.describe().empty());
  for (const Navigation n : {Navigation::Walk, Navigation::Orbit}) {
    const LiveTrial& t = trial(n);
    CameraNavigator navigator(n, t.start, 0.5f);
    for (int message = 0; message < 50; ++message) {  // the same input again and again: still within the bounds
      steer(navigator, t, input);
      require(withinLiveBounds(t, navigator.camera()));
    }
  }
  return 0;
}
