#pragma once
// A point on the k-th surface a pixel's eye ray crosses (layer k, 1 = front), with its exact
// shading normal, and the check that the surface is unambiguous around it: the shape tasks (gauge
// figure, relative depth) ask about a surface, so a probe near a silhouette, a crease or a place
// where the k-th crossing jumps to another surface is rejected (Cole et al. 2009 placed gauges away
// from such places too).
#include <optional>

#include <glm/glm.hpp>

#include "renderer/scene/scene.hpp"
#include "tasks/ray_layer_caster.hpp"
#include "tasks/view_geometry.hpp"

namespace tlab::tasks {

struct SurfaceSample {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0};  // the mesh's interpolated vertex normal (the one shading uses), unit, facing the eye
  int object = -1;
  int layer = 1;
};

// The smooth normal at a point of an object's triangle: the barycentric interpolation of the vertex
// normals, normalized (the face normal for a mesh without normals). Not turned to face anyone.
glm::dvec3 shadingNormal(const render::Scene& scene, int object, int triangle, glm::dvec3 point);

class SurfaceProbe {
 public:
  SurfaceProbe(const render::Scene& scene, const ViewGeometry& view);

  // The surface crossed `layer`-th by the ray through a continuous pixel position; none when the
  // ray crosses fewer surfaces.
  std::optional<SurfaceSample> at(glm::dvec2 pixel, int layer) const;

  // How well the surface at `centre` continues over a disk of `radiusPixels` around its pixel: the
  // rays through 8 points on the disk's rim must cross a `layer`-th surface of the same object, whose
  // normal is within `maxSpreadDegrees` of the centre's and whose point lies within the same angle
  // of the centre's tangent plane. Returns the largest normal angle seen (degrees), or none when a
  // rim ray fails.
  std::optional<double> continuity(const SurfaceSample& centre, glm::dvec2 pixel, double radiusPixels, double maxSpreadDegrees) const;

 private:
  const render::Scene& scene_;
  const ViewGeometry& view_;
  RayLayerCaster caster_;
  double mergeDistance_;
};

}  // namespace tlab::tasks
