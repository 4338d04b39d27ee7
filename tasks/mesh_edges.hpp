#pragma once
// The undirected edges of a welded mesh with the triangles using them: one triangle = a boundary
// edge, two = an interior edge, more = non-manifold.
#include <array>
#include <cstdint>
#include <vector>

#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {

struct MeshEdge {
  std::uint32_t v0 = 0, v1 = 0;               // v0 < v1
  std::vector<std::uint32_t> triangles;        // triangles using the edge
  bool firstRunsForward = true;                // triangles[0] traverses v0 → v1 in its winding

  bool isBoundary() const { return triangles.size() == 1; }
  bool isInterior() const { return triangles.size() == 2; }
};

std::vector<MeshEdge> meshEdges(const WeldedMesh& mesh);

}  // namespace tlab::tasks
