#include "tasks/welded_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tlab::tasks {

double WeldedMesh::area(std::size_t t) const {
  const auto& v = triangles[t];
  return 0.5 * glm::length(glm::cross(positions[v[1]] - positions[v[0]], positions[v[2]] - positions[v[0]]));
}

glm::dvec3 WeldedMesh::faceNormal(std::size_t t) const {
  const auto& v = triangles[t];
  const glm::dvec3 n = glm::cross(positions[v[1]] - positions[v[0]], positions[v[2]] - positions[v[0]]);
  const double len = glm::length(n);
  return len > 0.0 ? n / len : glm::dvec3(0.0);
}

glm::dvec3 WeldedMesh::centroid(std::size_t t) const {
  const auto& v = triangles[t];
  return (positions[v[0]] + positions[v[1]] + positions[v[2]]) / 3.0;
}

WeldedMesh weldMesh(const render::TriangleMesh& mesh, double relativeTolerance) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (const auto& p : mesh.positions) {
    lo = glm::min(lo, glm::dvec3(p));
    hi = glm::max(hi, glm::dvec3(p));
  }
  const double extent = mesh.positions.empty() ? 1.0 : std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-30});
  render::WeldedPositions<double> welded = render::weldPositions(mesh.positions, extent * relativeTolerance);
  WeldedMesh out;
  out.positions = std::move(welded.positions);
  const std::vector<std::uint32_t>& remap = welded.index;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::array<std::uint32_t, 3> w = {remap[tri[0]], remap[tri[1]], remap[tri[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;
    out.triangles.push_back(w);
    out.sourceTriangle.push_back(static_cast<std::uint32_t>(t));
  }
  return out;
}

}  // namespace tlab::tasks
