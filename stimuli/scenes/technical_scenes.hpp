#pragma once
// The technical illustrations of Diepstraten et al. (seed 001): a mug whose wall has an explicit
// inner surface with an opaque box inside it, a group of mugs, and a crank shaft inside a
// transparent cylinder housing. Deterministic; `seed` varies the mugs' arrangement.
#include <cstdint>

#include "renderer/scene/scene.hpp"

namespace tlab::stimuli {

// A mug with wall thickness: outer wall, inner wall, rim, outer and inner bottom, handle.
render::TriangleMesh makeMug(float radius, float height, float wallThickness, int segments);

render::Scene mugBoxScene();
render::Scene mugsScene(std::uint64_t seed, int count);
render::Scene crankCylinderScene();

}  // namespace tlab::stimuli
