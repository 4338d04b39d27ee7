#pragma once
// The objects a scene-level question is about (Elmqvist Sec. 4: "targets (red objects)", "red
// cones", "objects ... of the same type") and where they are on the floor plan.
//
// An object's kind is its name without a trailing number and separators ("cone-3", "cone_12",
// "cone 7" → "cone"). The floor plan is the world (x, z) plane seen from above (+y up).
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.hpp"

namespace tlab::tasks {

std::string objectKind(const std::string& objectName);

// Indices of the objects with the Target role when `kind` is empty, else of the objects of `kind`.
std::vector<std::size_t> selectTargets(const render::Scene& scene, const std::string& kind);

// "targets" or the kind, for question texts and messages.
std::string describeTargets(const std::string& kind);

// Area-weighted centroid of the mesh surface.
glm::dvec3 surfaceCentroid(const render::TriangleMesh& mesh);

inline glm::dvec2 floorPlanPoint(glm::dvec3 world) { return {world.x, world.z}; }

}  // namespace tlab::tasks
