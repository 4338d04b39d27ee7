#include "tasks/follow_boundary/boundary_loops.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "renderer/scene/mesh_welding.hpp"

namespace tlab::tasks {

BoundaryLoop::BoundaryLoop(std::vector<glm::dvec3> points, int object) : points_(std::move(points)), object_(object) {
  if (points_.size() < 2) throw std::invalid_argument("a boundary loop needs at least two points");
  arc_.push_back(0.0);
  for (std::size_t i = 0; i < points_.size(); ++i)
    arc_.push_back(arc_.back() + glm::length(points_[(i + 1) % points_.size()] - points_[i]));
}

double BoundaryLoop::wrap(double arc) const {
  const double w = std::fmod(arc, length());
  return w < 0.0 ? w + length() : w;
}

glm::dvec3 BoundaryLoop::pointAt(double arc) const {
  const double a = wrap(arc);
  const auto it = std::upper_bound(arc_.begin(), arc_.end(), a);
  const std::size_t i = std::min<std::size_t>(std::size_t(it - arc_.begin()) - 1, points_.size() - 1);
  const double segment = arc_[i + 1] - arc_[i];
  const double f = segment > 0.0 ? (a - arc_[i]) / segment : 0.0;
  return glm::mix(points_[i], points_[(i + 1) % points_.size()], f);
}

std::vector<BoundaryLoop> boundaryLoops(const WeldedMesh& mesh, int object) {
  // Directed boundary edges, as their single triangle traverses them.
  std::multimap<std::uint32_t, std::uint32_t> next;
  for (const auto& e : render::triangleEdges(mesh.triangles))
    if (e.isBoundary()) {
      if (e.firstRunsForward) next.emplace(e.v0, e.v1);
      else next.emplace(e.v1, e.v0);
    }
  std::vector<BoundaryLoop> loops;
  while (!next.empty()) {
    const std::uint32_t start = next.begin()->first;
    std::vector<glm::dvec3> points;
    std::uint32_t v = start;
    do {
      const auto it = next.find(v);
      if (it == next.end()) break;  // an open chain (non-manifold input): ends here
      points.push_back(mesh.positions[v]);
      v = it->second;
      next.erase(it);
    } while (v != start);
    if (points.size() >= 2) loops.emplace_back(std::move(points), object);
  }
  return loops;
}

}  // namespace tlab::tasks
