#pragma once
// A triangle mesh with coincident vertices welded (seams of duplicated vertices, UV-sphere poles)
// in double precision: the topology the tasks reason about — boundaries are edges used by one
// triangle of the welded mesh (render::triangleEdges), geodesics cross seams. The welding itself
// is the renderer's (renderer/scene/mesh_welding), in double.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/mesh_welding.hpp"
#include "renderer/scene/triangle_mesh.hpp"

namespace tlab::tasks {

struct WeldedMesh {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // triangles that collapsed are dropped
  std::vector<std::uint32_t> sourceTriangle;             // index in the original mesh, per triangle

  double area(std::size_t triangle) const;
  glm::dvec3 faceNormal(std::size_t triangle) const;     // unit; zero for a degenerate triangle
  glm::dvec3 centroid(std::size_t triangle) const;
};

// Welds vertices closer than `relativeTolerance` × the bounding-box extent.
WeldedMesh weldMesh(const render::TriangleMesh& mesh, double relativeTolerance = 1e-6);

}  // namespace tlab::tasks
