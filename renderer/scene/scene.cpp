#include "renderer/scene/scene.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tlab::render {

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const auto& o : objects) n += o.mesh.triangleCount();
  return n;
}

BoundingSphere Scene::boundingSphere() const {
  // Centre of the axis-aligned box, radius to the farthest vertex: simple and deterministic.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  bool any = false;
  for (const auto& o : objects)
    for (const auto& p : o.mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
      any = true;
    }
  if (!any) return {};
  BoundingSphere s;
  s.center = 0.5f * (lo + hi);
  float r2 = 0.0f;
  for (const auto& o : objects)
    for (const auto& p : o.mesh.positions) r2 = std::max(r2, glm::dot(p - s.center, p - s.center));
  s.radius = std::max(std::sqrt(r2), 1e-6f);
  return s;
}

void requireTriangles(const Scene& scene, const std::string& source) {
  if (scene.triangleCount() == 0) throw std::runtime_error(source + ": the scene has no triangles");
}

}  // namespace tlab::render
