#include "tasks/layer_index/layer_ground_truth.hpp"

#include <cmath>

namespace tlab::tasks {

LayerGroundTruth::LayerGroundTruth(const RayLayerCaster& caster, const ViewGeometry& view, double sceneRadius)
    : caster_(caster), view_(view), sceneRadius_(sceneRadius) {}

double LayerGroundTruth::depthTolerance(glm::dvec3 p) const {
  const double f = 1.5 * view_.pixelFootprint(view_.depth(p));
  return std::sqrt(2.0 * sceneRadius_ * f) + f;
}

int LayerGroundTruth::layersInFront(const Ray& ray, double depthLimit) const {
  const double cosine = glm::dot(ray.direction, view_.forward());
  int count = 0;
  for (const auto& hit : caster_.hits(ray, 1e-9 * sceneRadius_))
    if (hit.distance * cosine < depthLimit) ++count;
  return count;
}

int LayerGroundTruth::layerOf(glm::dvec3 p) const {
  const Ray ray{view_.eye(), glm::normalize(p - view_.eye())};
  return 1 + layersInFront(ray, view_.depth(p) - depthTolerance(p));
}

LayerVerdict LayerGroundTruth::verdict(glm::dvec3 p) const {
  LayerVerdict v;
  v.depthTolerance = depthTolerance(p);
  v.layer = layerOf(p);
  const double limit = view_.depth(p) - v.depthTolerance;
  const glm::ivec2 pixel(glm::floor(view_.project(p)));
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ++v.checkedPixels;
      if (1 + layersInFront(view_.rayThroughPixelCenter(pixel + glm::ivec2(dx, dy)), limit) == v.layer) ++v.agreeingPixels;
    }
  return v;
}

}  // namespace tlab::tasks
