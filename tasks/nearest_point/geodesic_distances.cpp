#include "tasks/nearest_point/geodesic_distances.hpp"

#include <algorithm>
#include <limits>
#include <queue>
#include <stdexcept>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

namespace tlab::tasks {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh>;
using ShortestPath = CGAL::Surface_mesh_shortest_path<Traits>;
using Face = Mesh::Face_index;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A CGAL surface of some of the welded triangles, with the map from welded triangle to face.
struct CgalPatch {
  Mesh mesh;
  std::vector<std::optional<Face>> faceOf;  // per welded triangle
  std::vector<int> rotation;                // CGAL's w0 = source(halfedge(f)) is the triangle's vertex `rotation`
  bool complete = true;                     // every selected triangle became a face

  CgalPatch(const WeldedMesh& welded, const std::vector<bool>& selected) : faceOf(welded.triangles.size()), rotation(welded.triangles.size(), 0) {
    std::vector<Mesh::Vertex_index> vertexOf(welded.positions.size(), Mesh::null_vertex());
    const auto vertex = [&](std::uint32_t v) {
      if (vertexOf[v] == Mesh::null_vertex()) vertexOf[v] = mesh.add_vertex({welded.positions[v].x, welded.positions[v].y, welded.positions[v].z});
      return vertexOf[v];
    };
    for (std::size_t t = 0; t < welded.triangles.size(); ++t) {
      if (!selected[t]) continue;
      const auto& tri = welded.triangles[t];
      const Face f = mesh.add_face(vertex(tri[0]), vertex(tri[1]), vertex(tri[2]));
      if (f == Mesh::null_face()) {
        complete = false;
        continue;
      }
      faceOf[t] = f;
      const auto first = mesh.source(mesh.halfedge(f));
      int r = 0;
      while (vertexOf[tri[r]] != first) ++r;
      rotation[t] = r;
    }
  }

  // CGAL orders barycentrics as (source(h), target(h), target(next(h))) with h = halfedge(f).
  Traits::Barycentric_coordinates location(const SurfacePoint& p) const {
    const int r = rotation[p.triangle];
    return {p.barycentric[r], p.barycentric[(r + 1) % 3], p.barycentric[(r + 2) % 3]};
  }
};

}  // namespace

struct GeodesicDistances::Surface {
  WeldedMesh welded;
  std::vector<std::vector<std::pair<std::uint32_t, double>>> neighbours;  // vertex graph with edge lengths
  double longestEdge = 0.0;
  CgalPatch whole;

  explicit Surface(const WeldedMesh& w) : welded(w), neighbours(w.positions.size()), whole(w, std::vector<bool>(w.triangles.size(), true)) {
    for (const auto& t : w.triangles)
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t a = t[i], b = t[(i + 1) % 3];
        const double length = glm::length(w.positions[a] - w.positions[b]);
        neighbours[a].push_back({b, length});
        neighbours[b].push_back({a, length});
        longestEdge = std::max(longestEdge, length);
      }
  }

  // Dijkstra from the source point through its triangle's corners.
  std::vector<double> vertexDistances(const SurfacePoint& source) const {
    std::vector<double> d(welded.positions.size(), kInfinity);
    using Entry = std::pair<double, std::uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    const glm::dvec3 a = source.position(welded);
    for (const auto v : welded.triangles[source.triangle]) {
      d[v] = glm::length(welded.positions[v] - a);
      queue.push({d[v], v});
    }
    while (!queue.empty()) {
      const auto [dist, v] = queue.top();
      queue.pop();
      if (dist > d[v]) continue;
      for (const auto& [w, length] : neighbours[v])
        if (dist + length < d[w]) queue.push({d[w] = dist + length, w});
    }
    return d;
  }
};

GeodesicDistances::GeodesicDistances(const WeldedMesh& welded) : surface_(std::make_unique<Surface>(welded)) {}
GeodesicDistances::~GeodesicDistances() = default;
GeodesicDistances::GeodesicDistances(GeodesicDistances&&) noexcept = default;
GeodesicDistances& GeodesicDistances::operator=(GeodesicDistances&&) noexcept = default;

bool GeodesicDistances::hasTriangle(std::uint32_t t) const {
  return t < surface_->whole.faceOf.size() && surface_->whole.faceOf[t].has_value();
}

std::vector<std::optional<double>> GeodesicDistances::edgePathUpperBounds(const SurfacePoint& source,
                                                                          const std::vector<SurfacePoint>& targets) const {
  const WeldedMesh& w = surface_->welded;
  const std::vector<double> d = surface_->vertexDistances(source);
  std::vector<std::optional<double>> out;
  for (const auto& t : targets) {
    const glm::dvec3 p = t.position(w);
    double best = t.triangle == source.triangle ? glm::length(p - source.position(w)) : kInfinity;
    for (const auto v : w.triangles[t.triangle]) best = std::min(best, d[v] + glm::length(w.positions[v] - p));
    out.push_back(best < kInfinity ? std::optional<double>(best) : std::nullopt);
  }
  return out;
}

namespace {

// The largest of the upper bounds that exist (0 when none does).
double largestBound(const std::vector<std::optional<double>>& bounds) {
  double largest = 0.0;
  for (const auto& b : bounds)
    if (b) largest = std::max(largest, *b);
  return largest;
}

}  // namespace

void GeodesicDistances::requireManifold(const SurfacePoint& source, const std::vector<SurfacePoint>& targets) const {
  for (const auto& p : targets)
    if (!hasTriangle(p.triangle)) throw std::invalid_argument("geodesic distance: point on a non-manifold triangle");
  if (!hasTriangle(source.triangle)) throw std::invalid_argument("geodesic distance: point on a non-manifold triangle");
}

std::vector<bool> GeodesicDistances::selectPatch(const SurfacePoint& source, double radius, std::size_t* count) const {
  const WeldedMesh& w = surface_->welded;
  const glm::dvec3 a = source.position(w);
  const double reach = radius + surface_->longestEdge;  // a face touching B(a, radius) has a corner within this
  std::vector<bool> selected(w.triangles.size(), false);
  *count = 0;
  for (std::size_t t = 0; t < w.triangles.size(); ++t) {
    const auto& tri = w.triangles[t];
    const double nearest = std::min({glm::length(w.positions[tri[0]] - a), glm::length(w.positions[tri[1]] - a),
                                     glm::length(w.positions[tri[2]] - a)});
    if (nearest <= reach && surface_->whole.faceOf[t]) selected[t] = true, ++*count;
  }
  return selected;
}

std::size_t GeodesicDistances::patchFaces(const SurfacePoint& source, double radius) const {
  std::size_t count = 0;
  selectPatch(source, radius, &count);
  return count;
}

std::size_t GeodesicDistances::faceCount() const { return surface_->welded.triangles.size(); }

std::vector<double> GeodesicDistances::onPatch(const SurfacePoint& source, const std::vector<SurfacePoint>& targets, double radius) const {
  const WeldedMesh& w = surface_->welded;
  std::size_t count = 0;
  const std::vector<bool> selected = selectPatch(source, radius, &count);
  std::optional<CgalPatch> local;
  if (count < w.triangles.size()) {
    local.emplace(w, selected);
    if (!local->complete) local.reset();  // a non-manifold patch: use the whole surface
  }
  const CgalPatch& patch = local ? *local : surface_->whole;

  ShortestPath paths(patch.mesh);
  paths.add_source_point(*patch.faceOf[source.triangle], patch.location(source));
  paths.build_sequence_tree();
  std::vector<double> out;
  for (const auto& t : targets)
    out.push_back(patch.faceOf[t.triangle] ? paths.shortest_distance_to_source_points(*patch.faceOf[t.triangle], patch.location(t)).first : -1.0);
  return out;
}

std::vector<std::optional<double>> GeodesicDistances::fromSource(const SurfacePoint& source,
                                                                 const std::vector<SurfacePoint>& targets) const {
  requireManifold(source, targets);
  // The patch of faces touching B(a, R), R = the largest upper bound (see the header).
  const auto bounds = edgePathUpperBounds(source, targets);
  const auto d = onPatch(source, targets, largestBound(bounds));
  std::vector<std::optional<double>> out;
  for (std::size_t i = 0; i < targets.size(); ++i) out.push_back(bounds[i] && d[i] >= 0.0 ? std::optional<double>(d[i]) : std::nullopt);
  return out;
}

std::vector<CappedDistance> GeodesicDistances::fromSourceWithin(const SurfacePoint& source, const std::vector<SurfacePoint>& targets,
                                                                double cap) const {
  requireManifold(source, targets);
  const auto bounds = edgePathUpperBounds(source, targets);
  const double radius = std::min(largestBound(bounds), cap);
  const auto d = onPatch(source, targets, radius);
  const glm::dvec3 a = source.position(surface_->welded);
  std::vector<CappedDistance> out(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i) {
    CappedDistance& c = out[i];
    c.reachable = bounds[i].has_value();
    if (!c.reachable) continue;
    // Every path of length ≤ radius lies on the patch, so a patch distance ≤ radius is exact and
    // anything else is > radius (and never below the straight line).
    if (d[i] >= 0.0 && d[i] <= radius) {
      c.exact = d[i];
      c.lowerBound = d[i];
    } else {
      c.lowerBound = std::max(radius, glm::length(targets[i].position(surface_->welded) - a));
    }
  }
  return out;
}

}  // namespace tlab::tasks
