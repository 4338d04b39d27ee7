#include "tasks/mesh_edges.hpp"

#include <algorithm>
#include <tuple>

namespace tlab::tasks {

std::vector<MeshEdge> meshEdges(const WeldedMesh& mesh) {
  struct HalfEdge {
    std::uint32_t lo, hi, triangle;
    bool forward;
  };
  std::vector<HalfEdge> halves;
  halves.reserve(mesh.triangles.size() * 3);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[t][i], b = mesh.triangles[t][(i + 1) % 3];
      halves.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(halves.begin(), halves.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
  });
  std::vector<MeshEdge> edges;
  for (std::size_t i = 0; i < halves.size();) {
    MeshEdge e;
    e.v0 = halves[i].lo;
    e.v1 = halves[i].hi;
    e.firstRunsForward = halves[i].forward;
    std::size_t j = i;
    for (; j < halves.size() && halves[j].lo == e.v0 && halves[j].hi == e.v1; ++j) e.triangles.push_back(halves[j].triangle);
    edges.push_back(std::move(e));
    i = j;
  }
  return edges;
}

}  // namespace tlab::tasks
