#pragma once
// Silhouette edges of a scene seen from an eye point, by Carnecky Fig. 2's definition: the
// union of the interior silhouette (where n·v changes sign along the surface, i.e. an edge whose
// two triangles face opposite ways as seen from the eye) and the surface boundary (edges used by
// one triangle after welding).
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.hpp"
#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {

enum class SilhouetteKind { Contour, Boundary };

struct SilhouetteEdge {
  glm::dvec3 p0{0.0}, p1{0.0};
  SilhouetteKind kind = SilhouetteKind::Contour;
  int object = -1;
  double length() const { return glm::length(p1 - p0); }
};

// `welded` holds one welded mesh per scene object.
std::vector<SilhouetteEdge> silhouetteEdges(const std::vector<WeldedMesh>& welded, glm::dvec3 eye);

const char* silhouetteKindName(SilhouetteKind kind);

}  // namespace tlab::tasks
