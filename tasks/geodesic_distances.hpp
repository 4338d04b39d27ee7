#pragma once
// Exact geodesic distances on a triangle mesh (Carnecky Sec. 8.1, Task 3 "geodesically closest"),
// with CGAL's Surface_mesh_shortest_path (Xin–Wang's exact algorithm) on a CGAL::Surface_mesh.
// CGAL stays inside geodesic_distances.cpp.
//
// Locality, still exact: a surface path of length L from a stays in the Euclidean ball B(a, L).
// Paths along mesh edges (Dijkstra) give upper bounds Uᵢ ≥ d(a, tᵢ), so every shortest path to the
// targets lies on the faces that touch B(a, max Uᵢ); the exact algorithm runs on that patch only
// (removing faces cannot shorten a path, and no shortest path uses a removed face).
#include <memory>
#include <optional>
#include <vector>

#include "tasks/surface_point.hpp"
#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {

class GeodesicDistances {
 public:
  explicit GeodesicDistances(const WeldedMesh& mesh);
  ~GeodesicDistances();
  GeodesicDistances(GeodesicDistances&&) noexcept;
  GeodesicDistances& operator=(GeodesicDistances&&) noexcept;

  // False for a triangle CGAL's halfedge structure could not take (non-manifold input).
  bool hasTriangle(std::uint32_t triangle) const;
  // Upper bounds on the geodesic distances: the shortest paths source → mesh vertices (along
  // edges) → target; std::nullopt where no path exists (another connected component).
  std::vector<std::optional<double>> edgePathUpperBounds(const SurfacePoint& source, const std::vector<SurfacePoint>& targets) const;
  // Exact geodesic distance from `source` to each target; std::nullopt where no path exists.
  std::vector<std::optional<double>> fromSource(const SurfacePoint& source, const std::vector<SurfacePoint>& targets) const;

 private:
  struct Surface;
  std::unique_ptr<Surface> surface_;
};

}  // namespace tlab::tasks
