#pragma once
// Object-space silhouette edges (Diepstraten et al. 2002, Sec. 5, after Appel): the edge
// adjacency of a mesh after welding coincident vertices (scene/mesh_welding, in float), and per view the edges whose two faces
// face opposite ways as seen from the eye (Diepstraten Eq. 1), plus boundary edges (used by one
// face), which outline open surfaces.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/mesh_welding.hpp"
#include "renderer/scene/triangle_mesh.hpp"

namespace tlab::render {

constexpr std::uint32_t kNoFace = 0xFFFFFFFFu;

struct MeshEdge {
  std::uint32_t a = 0, b = 0;                     // welded vertex indices, a < b
  std::uint32_t face0 = kNoFace, face1 = kNoFace;  // face1 = kNoFace: a boundary edge
};

struct SilhouetteSegment {
  glm::vec3 p0{0.0f}, p1{0.0f};
};

// Built once per mesh; silhouettes() is then one pass over the edges per view.
class EdgeAdjacency {
 public:
  // Welds vertices closer than `relativeTolerance` × the bounding-box diagonal.
  explicit EdgeAdjacency(const TriangleMesh& mesh, float relativeTolerance = 1e-5f);
  const std::vector<glm::vec3>& positions() const { return positions_; }
  // For each vertex of the input mesh, its welded vertex.
  const std::vector<std::uint32_t>& weldedIndex() const { return weldedIndex_; }
  const std::vector<MeshEdge>& edges() const { return edges_; }
  const std::vector<glm::vec3>& faceNormals() const { return faceNormals_; }  // unit, from the winding

  // Diepstraten Eq. 1: (n1·(p − o))·(n2·(p − o)) < 0 for a point p on the edge and the eye o;
  // boundary edges always count. Buried edges never do.
  std::vector<SilhouetteSegment> silhouettes(glm::vec3 eye) const;
  // Edges whose midpoint lies inside another closed part of the same mesh (a shaft's end inside
  // a crank web): they outline nothing that can be seen, so they are no silhouettes.
  const std::vector<bool>& buried() const { return buried_; }

 private:
  void collectEdges();
  void findBuriedEdges();
  std::vector<bool> buried_;
  std::vector<std::array<std::uint32_t, 3>> faces_;  // welded triangles, one per face normal
  std::vector<glm::vec3> positions_;
  std::vector<std::uint32_t> weldedIndex_;
  std::vector<MeshEdge> edges_;
  std::vector<glm::vec3> faceNormals_;
};

}  // namespace tlab::render
