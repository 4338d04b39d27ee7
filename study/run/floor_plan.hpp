#pragma once
// FloorPlan: the map a participant clicks to answer "where is it?" (Elmqvist T3: mark the target
// on a 2-D floor plan seen from above). The scene is rendered opaque from straight above with a
// narrow field of view (nearly orthographic), and a click on the plan maps back to world (x, z)
// by intersecting the pixel's viewing ray with the floor plane y = floorY (the scene's lowest
// vertex).
#include <glm/glm.hpp>

#include "renderer/scene/camera.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::study {

struct FloorPlan {
  render::Camera camera;
  int width = 0, height = 0;
  double floorY = 0.0;

  // Pixel (continuous, row 0 = top) → world (x, z) on the floor plane.
  glm::dvec2 worldAt(glm::dvec2 pixel) const;
  // World point → pixel (continuous, row 0 = top).
  glm::dvec2 pixelOf(glm::dvec3 world) const;
};

// The top-down view of a scene for a plan of width × height pixels.
FloorPlan makeFloorPlan(const render::Scene& scene, int width, int height);

}  // namespace tlab::study
