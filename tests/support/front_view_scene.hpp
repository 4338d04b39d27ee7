#pragma once
// A test scene of the given objects seen from (0, 0, 6) looking at the origin (near 1, far 12),
// on a background that no object uses (green by default), for GL tests that read pixels.
#include <utility>
#include <vector>

#include "renderer/scene/scene.hpp"

namespace tlab::testing {

inline render::Scene frontViewScene(std::vector<render::SceneObject> objects, glm::vec4 background = {0, 1, 0, 1}) {
  render::Scene s;
  s.objects = std::move(objects);
  s.background = background;
  render::Camera c;
  c.eye = {0, 0, 6};
  c.target = {0, 0, 0};
  c.nearPlane = 1.0f;
  c.farPlane = 12.0f;
  s.camera = c;
  return s;
}

}  // namespace tlab::testing
