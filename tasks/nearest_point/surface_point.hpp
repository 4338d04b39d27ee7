#pragma once
// A point on a welded mesh: a triangle and barycentric coordinates (weights of its three
// vertices in winding order), and area-uniform random sampling of such points.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/seeded_random.hpp"
#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {

struct SurfacePoint {
  std::uint32_t triangle = 0;
  glm::dvec3 barycentric{1.0 / 3.0};

  glm::dvec3 position(const WeldedMesh& mesh) const;
};

// Samples points uniformly by area (a triangle by area, then √-warped barycentrics).
class SurfaceSampler {
 public:
  explicit SurfaceSampler(const WeldedMesh& mesh);
  double totalArea() const { return cumulativeArea_.empty() ? 0.0 : cumulativeArea_.back(); }
  SurfacePoint sample(core::SeededRandom& random) const;

 private:
  std::vector<double> cumulativeArea_;
};

}  // namespace tlab::tasks
