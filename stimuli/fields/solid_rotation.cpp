#include "stimuli/fields/solid_rotation.hpp"

#include <cmath>

namespace tlab::stimuli {

glm::dvec3 SolidRotation::velocity(const glm::dvec3& x, double) const { return {-omega_ * x.y, omega_ * x.x, 0.0}; }

glm::dmat3 SolidRotation::jacobian(const glm::dvec3&, double) const {
  glm::dmat3 j(0.0);
  j[0] = {0.0, omega_, 0.0};   // ∂v/∂x
  j[1] = {-omega_, 0.0, 0.0};  // ∂v/∂y
  return j;
}

glm::dvec3 SolidRotation::exactPosition(const glm::dvec3& x0, double t0, double t1) const {
  const double a = omega_ * (t1 - t0), c = std::cos(a), s = std::sin(a);
  return {c * x0.x - s * x0.y, s * x0.x + c * x0.y, x0.z};
}

}  // namespace tlab::stimuli
