#pragma once
// Every intersection of a ray with the scene's triangles, sorted by distance: the exact layers a
// ray passes through. Built on a CGAL AABB tree (CGAL::AABB_tree with AABB_triangle_primitive);
// CGAL stays inside ray_layer_caster.cpp.
#include <memory>
#include <vector>

#include "renderer/scene/scene.hpp"
#include "tasks/view_geometry.hpp"

namespace tlab::tasks {

struct RayHit {
  double distance = 0.0;  // along the (unit) ray direction
  int object = -1;
  int triangle = -1;      // index into the object's mesh triangles
};

class RayLayerCaster {
 public:
  explicit RayLayerCaster(const render::Scene& scene);
  ~RayLayerCaster();
  RayLayerCaster(RayLayerCaster&&) noexcept;
  RayLayerCaster& operator=(RayLayerCaster&&) noexcept;

  // All hits at distance > 0, nearest first. Hits closer than `mergeDistance` to the previous one
  // are one surface crossing (a ray through a shared edge or vertex meets several triangles).
  std::vector<RayHit> hits(const Ray& ray, double mergeDistance) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace tlab::tasks
