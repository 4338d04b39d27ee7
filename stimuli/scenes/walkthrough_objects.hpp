#pragma once
// The WALKTHROUGH's objects (Elmqvist seed 004, Sec. VI.4: "pets, vehicles, furniture"), each
// built from a few primitives so that the kinds are easy to tell apart: dog, cat, car, bicycle,
// chair, table, lamp, plant, bed, and the trophy used as the unique T3 target. Meshes stand on
// y = 0, centred on the origin, about one metre across.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/triangle_mesh.hpp"

namespace tlab::stimuli {

struct WalkthroughObjectModel {
  std::string kind;
  render::TriangleMesh mesh;
  glm::vec4 color;
};

// Every kind, in a fixed order; the trophy is last.
const std::vector<std::string>& walkthroughObjectKinds();
// Throws std::invalid_argument for an unknown kind.
WalkthroughObjectModel makeWalkthroughObject(const std::string& kind);

}  // namespace tlab::stimuli
