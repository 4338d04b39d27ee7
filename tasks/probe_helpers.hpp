#pragma once
// Small pieces shared by the tasks' probe selection.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/seeded_random.hpp"
#include "renderer/scene/scene.hpp"
#include "tasks/question.hpp"
#include "tasks/view_geometry.hpp"
#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {

// One welded mesh per scene object, in object order.
std::vector<WeldedMesh> weldSceneObjects(const render::Scene& scene);

// A ProbePoint with its pixel position in `view`.
ProbePoint probePoint(const ViewGeometry& view, std::string label, std::string role, glm::dvec3 world, int object);

// A continuous pixel position uniform over the image less a margin on every side; x is drawn before
// y (two statements: the order of arguments in one call is not fixed by C++, seeds must give the same
// probes with every compiler).
glm::dvec2 randomPixel(core::SeededRandom& random, int width, int height, double margin);

// The smallest pixel distance between `pixel` and any of `others` (infinity when empty).
double nearestPixelDistance(glm::dvec2 pixel, const std::vector<glm::dvec2>& others);

// Throws std::runtime_error: "<task>: found only K of N questions ... (<hint>)".
[[noreturn]] void throwTooFew(const std::string& task, std::size_t found, int wanted, const std::string& hint);

// The count must be ≥ 1.
void requirePositiveCount(const std::string& task, int count);

}  // namespace tlab::tasks
