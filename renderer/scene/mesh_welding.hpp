#pragma once
// Welded mesh topology, once for the whole system: vertices closer than a tolerance become one
// (seams of duplicated vertices, UV-sphere poles), and the undirected edges of the welded
// triangles with the triangles that use them. The renderer's silhouette edges
// (ops/silhouette_edges, float: its lines are drawn into pictures) and the tasks' ground truth
// (tasks/welded_mesh, double) both rest on it. Templated on the scalar so each keeps its own
// precision: a double weld of the renderer's float positions could round differently and move a
// line by a pixel.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tlab::render {

template <typename T>
struct WeldedPositions {
  std::vector<glm::vec<3, T>> positions;  // one per welded vertex, in order of first appearance
  std::vector<std::uint32_t> index;       // per input vertex: its welded vertex
};

// Welds positions closer than `tolerance` (absolute): each vertex joins the first earlier welded
// vertex within the tolerance, else starts a new one. Instantiated for float and double.
template <typename T>
WeldedPositions<T> weldPositions(const std::vector<glm::vec3>& positions, T tolerance);

// An undirected edge of a triangle list: one triangle = a boundary edge, two = an interior edge,
// more = non-manifold.
struct TriangleEdge {
  std::uint32_t v0 = 0, v1 = 0;         // v0 < v1
  std::vector<std::uint32_t> triangles;  // triangles using the edge, ascending
  bool firstRunsForward = true;          // triangles[0] traverses v0 → v1 in its winding

  bool isBoundary() const { return triangles.size() == 1; }
  bool isInterior() const { return triangles.size() == 2; }
};

// The edges of `triangles` (none collapsed), ordered by (v0, v1).
std::vector<TriangleEdge> triangleEdges(const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace tlab::render
