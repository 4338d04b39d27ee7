#pragma once
// An indexed triangle mesh in world space with per-vertex position, normal and surface
// parameters (s, t) — the (s, t) of integral surfaces (IRIS Sec. 2) or TEXCOORD_0 of a glTF.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tlab::render {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   // unit length; same size as positions
  std::vector<glm::vec2> st;        // surface parameters; same size as positions
  std::vector<std::array<std::uint32_t, 3>> triangles;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
};

// Area-weighted vertex normals, for meshes that come without them.
void computeVertexNormals(TriangleMesh& mesh);

// Connected component id per vertex. Vertices at the same position (to a tolerance relative to
// the mesh size) are welded first, so seams of duplicated vertices do not split a surface.
std::vector<std::uint32_t> connectedComponents(const TriangleMesh& mesh);

// Applies an affine transform to positions and (inverse-transpose) normals.
void transformMesh(TriangleMesh& mesh, const glm::mat4& transform);

// Appends `other` to `mesh`, offsetting indices.
void appendMesh(TriangleMesh& mesh, const TriangleMesh& other);

}  // namespace tlab::render
