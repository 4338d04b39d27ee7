#include "tasks/probe_helpers.hpp"

#include <limits>
#include <stdexcept>

namespace tlab::tasks {

std::vector<WeldedMesh> weldSceneObjects(const render::Scene& scene) {
  std::vector<WeldedMesh> out;
  for (const auto& o : scene.objects) out.push_back(weldMesh(o.mesh));
  return out;
}

ProbePoint probePoint(const ViewGeometry& view, std::string label, std::string role, glm::dvec3 world, int object) {
  return {std::move(label), std::move(role), world, view.project(world), object};
}

glm::dvec2 randomPixel(core::SeededRandom& random, int width, int height, double margin) {
  const double x = margin + double(random.uniform()) * (width - 2.0 * margin);
  const double y = margin + double(random.uniform()) * (height - 2.0 * margin);
  return {x, y};
}

double nearestPixelDistance(glm::dvec2 pixel, const std::vector<glm::dvec2>& others) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& o : others) best = std::min(best, glm::length(o - pixel));
  return best;
}

void throwTooFew(const std::string& task, std::size_t found, int wanted, const std::string& hint) {
  throw std::runtime_error(task + ": found only " + std::to_string(found) + " of " + std::to_string(wanted) +
                           " questions that meet every rule on this scene and view (" + hint + ")");
}

void requirePositiveCount(const std::string& task, int count) {
  if (count < 1) throw std::invalid_argument(task + ": the question count must be at least 1");
}

}  // namespace tlab::tasks
