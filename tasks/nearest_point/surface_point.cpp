#include "tasks/nearest_point/surface_point.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tlab::tasks {

glm::dvec3 SurfacePoint::position(const WeldedMesh& mesh) const {
  const auto& v = mesh.triangles[triangle];
  return barycentric.x * mesh.positions[v[0]] + barycentric.y * mesh.positions[v[1]] + barycentric.z * mesh.positions[v[2]];
}

SurfaceSampler::SurfaceSampler(const WeldedMesh& mesh) {
  double sum = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) cumulativeArea_.push_back(sum += mesh.area(t));
}

SurfacePoint SurfaceSampler::sample(core::SeededRandom& random) const {
  if (totalArea() <= 0.0) throw std::runtime_error("cannot sample a surface of zero area");
  // Two uniforms with 24 bits each pick the triangle; then the standard √ warp (Turk 1990).
  // (Two statements: the operands of + are unsequenced, and compilers differ in which runs first.)
  const double high = double(random.bits() >> 8);
  const double low = double(random.bits() >> 8);
  const double u = (high + low / 16777216.0) / 16777216.0;
  const auto it = std::upper_bound(cumulativeArea_.begin(), cumulativeArea_.end(), u * totalArea());
  const std::size_t t = std::min<std::size_t>(std::size_t(it - cumulativeArea_.begin()), cumulativeArea_.size() - 1);
  const double r1 = std::sqrt(double(random.uniform())), r2 = double(random.uniform());
  return {static_cast<std::uint32_t>(t), {1.0 - r1, r1 * (1.0 - r2), r1 * r2}};
}

}  // namespace tlab::tasks
