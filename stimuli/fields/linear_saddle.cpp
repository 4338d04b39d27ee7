#include "stimuli/fields/linear_saddle.hpp"

#include <cmath>

namespace tlab::stimuli {

glm::dvec3 LinearSaddle::velocity(const glm::dvec3& x, double) const { return {a_ * x.x, -a_ * x.y, b_ * x.z}; }

glm::dmat3 LinearSaddle::jacobian(const glm::dvec3&, double) const {
  return glm::dmat3(glm::dvec3(a_, 0.0, 0.0), glm::dvec3(0.0, -a_, 0.0), glm::dvec3(0.0, 0.0, b_));
}

glm::dvec3 LinearSaddle::exactPosition(const glm::dvec3& x0, double t0, double t1) const {
  const double dt = t1 - t0;
  return {x0.x * std::exp(a_ * dt), x0.y * std::exp(-a_ * dt), x0.z * std::exp(b_ * dt)};
}

}  // namespace tlab::stimuli
