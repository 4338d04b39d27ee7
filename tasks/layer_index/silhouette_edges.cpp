#include "tasks/layer_index/silhouette_edges.hpp"

#include "renderer/scene/mesh_welding.hpp"

namespace tlab::tasks {

namespace {
// Sign of n·v for a triangle (v from the eye to the triangle): +1 back-facing, −1 front-facing.
int facing(const WeldedMesh& mesh, std::uint32_t t, glm::dvec3 eye) {
  const double d = glm::dot(mesh.faceNormal(t), mesh.centroid(t) - eye);
  return d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
}
}  // namespace

std::vector<SilhouetteEdge> silhouetteEdges(const std::vector<WeldedMesh>& welded, glm::dvec3 eye) {
  std::vector<SilhouetteEdge> out;
  for (std::size_t o = 0; o < welded.size(); ++o) {
    const WeldedMesh& mesh = welded[o];
    for (const auto& e : render::triangleEdges(mesh.triangles)) {
      SilhouetteEdge s{mesh.positions[e.v0], mesh.positions[e.v1], SilhouetteKind::Boundary, int(o)};
      if (e.isBoundary()) {
        out.push_back(s);
      } else if (e.isInterior() && facing(mesh, e.triangles[0], eye) * facing(mesh, e.triangles[1], eye) < 0) {
        s.kind = SilhouetteKind::Contour;
        out.push_back(s);
      }
    }
  }
  return out;
}

const char* silhouetteKindName(SilhouetteKind kind) {
  return kind == SilhouetteKind::Contour ? "interior-silhouette" : "boundary";
}

}  // namespace tlab::tasks
