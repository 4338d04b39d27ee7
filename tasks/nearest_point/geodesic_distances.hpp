#pragma once
// Exact geodesic distances on a triangle mesh (Carnecky Sec. 8.1, Task 3 "geodesically closest"),
// with CGAL's Surface_mesh_shortest_path (Xin–Wang's exact algorithm) on a CGAL::Surface_mesh.
// CGAL stays inside geodesic_distances.cpp.
//
// Locality, still exact: a surface path of length L from a stays in the Euclidean ball B(a, L).
// Paths along mesh edges (Dijkstra) give upper bounds Uᵢ ≥ d(a, tᵢ), so every shortest path to the
// targets lies on the faces that touch B(a, max Uᵢ); the exact algorithm runs on that patch only
// (removing faces cannot shorten a path, and no shortest path uses a removed face).
//
// Capped: the same argument with a radius ρ smaller than the bounds gives every distance ≤ ρ
// exactly and proves the others > ρ — for the nearest-point task, which only needs the nearest
// candidate exactly and the others "far enough", this keeps the exact algorithm on a small patch.
#include <memory>
#include <optional>
#include <vector>

#include "tasks/nearest_point/surface_point.hpp"
#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {

// A geodesic distance known exactly up to a cap, or only as "farther than the cap".
struct CappedDistance {
  bool reachable = false;       // on the source's connected component
  std::optional<double> exact;  // the exact distance when it is ≤ the cap
  double lowerBound = 0.0;      // the exact distance, or a proven lower bound max(cap, Euclidean)
};

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
  // How many faces the exact computation up to `radius` from `source` runs on (its cost grows
  // faster than this), and how many the mesh has.
  std::size_t patchFaces(const SurfacePoint& source, double radius) const;
  std::size_t faceCount() const;
  // Exact distances up to `cap`; farther targets get a lower bound (see the header comment).
  std::vector<CappedDistance> fromSourceWithin(const SurfacePoint& source, const std::vector<SurfacePoint>& targets, double cap) const;

 private:
  struct Surface;
  std::vector<bool> selectPatch(const SurfacePoint& source, double radius, std::size_t* count) const;
  // Distances on the patch of faces touching B(source, radius); negative where the patch has no path.
  std::vector<double> onPatch(const SurfacePoint& source, const std::vector<SurfacePoint>& targets, double radius) const;
  void requireManifold(const SurfacePoint& source, const std::vector<SurfacePoint>& targets) const;
  std::unique_ptr<Surface> surface_;
};

}  // namespace tlab::tasks
