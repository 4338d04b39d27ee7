#include "stimuli/fields/stiff_relaxation_field.hpp"

#include <cmath>

namespace tlab::stimuli {

glm::dvec3 StiffRelaxationField::velocity(const glm::dvec3& p, double) const {
  const double vx = -omega_ * p.y, vy = omega_ * p.x;
  const double dgdt = kappa_ * (p.y * vx + p.x * vy);  // ∇g · (ẋ, ẏ) = κ ω (x² − y²)
  return {vx, vy, -lambda_ * (p.z - manifold(p.x, p.y)) + dgdt};
}

glm::dmat3 StiffRelaxationField::jacobian(const glm::dvec3& p, double) const {
  glm::dmat3 j(0.0);
  j[0] = {0.0, omega_, lambda_ * kappa_ * p.y + 2.0 * kappa_ * omega_ * p.x};
  j[1] = {-omega_, 0.0, lambda_ * kappa_ * p.x - 2.0 * kappa_ * omega_ * p.y};
  j[2] = {0.0, 0.0, -lambda_};
  return j;
}

glm::dvec3 StiffRelaxationField::exactPosition(const glm::dvec3& p0, double t0, double t1) const {
  const double a = omega_ * (t1 - t0), c = std::cos(a), s = std::sin(a);
  const double x = c * p0.x - s * p0.y, y = s * p0.x + c * p0.y;
  return {x, y, manifold(x, y) + (p0.z - manifold(p0.x, p0.y)) * std::exp(-lambda_ * (t1 - t0))};
}

}  // namespace tlab::stimuli
