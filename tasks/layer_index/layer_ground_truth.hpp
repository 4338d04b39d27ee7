#pragma once
// Carnecky Sec. 8.1, Task 1 "layer index": the layer (1 = front) on which a surface point lies
// along the eye ray through it, by exact ray casting, and the ambiguity check of its pixel.
//
// Layer of p = 1 + the number of surface crossings on the eye ray through p whose view depth is
// less than depth(p) − δ. The tolerance δ keeps the probe's own surface (which a tangent ray
// grazes at a silhouette) out of the count: within 1.5 pixels of p a surface whose radius of
// curvature is at most the scene radius R moves in depth by at most √(2 R f) with f the world
// size of 1.5 pixels at p (a circle's sagitta), so δ = √(2 R f) + f.
//
// A probe is unambiguous when the rays through the centres of the 3 × 3 pixels around it all
// count the same layers in front of depth(p) − δ as the ray through p itself.
#include <glm/glm.hpp>

#include "tasks/ray_layer_caster.hpp"
#include "tasks/view_geometry.hpp"

namespace tlab::tasks {

struct LayerVerdict {
  int layer = 0;              // 1-based, along the eye ray through the point
  int agreeingPixels = 0;     // of the 3 × 3 neighbourhood
  int checkedPixels = 0;
  double depthTolerance = 0;  // δ
  bool unambiguous() const { return agreeingPixels == checkedPixels; }
};

class LayerGroundTruth {
 public:
  // `sceneRadius` = R above (the scene's bounding-sphere radius).
  LayerGroundTruth(const RayLayerCaster& caster, const ViewGeometry& view, double sceneRadius);

  double depthTolerance(glm::dvec3 point) const;
  int layerOf(glm::dvec3 point) const;
  LayerVerdict verdict(glm::dvec3 point) const;

 private:
  int layersInFront(const Ray& ray, double depthLimit) const;

  const RayLayerCaster& caster_;
  const ViewGeometry& view_;
  double sceneRadius_;
};

}  // namespace tlab::tasks
