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

std::optional<BoundingBox> Scene::boundingBox() const {
  BoundingBox box{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(std::numeric_limits<float>::lowest())};
  bool any = false;
  for (const auto& o : objects)
    for (const auto& p : o.mesh.positions) {
      box.lo = glm::min(box.lo, p);
      box.hi = glm::max(box.hi, p);
      any = true;
    }
  if (!any) return std::nullopt;
  return box;
}

BoundingSphere Scene::boundingSphere() const {
  // Centre of the axis-aligned box, radius to the farthest vertex: simple and deterministic.
  const std::optional<BoundingBox> box = boundingBox();
  if (!box) return {};
  BoundingSphere s;
  s.center = 0.5f * (box->lo + box->hi);
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
