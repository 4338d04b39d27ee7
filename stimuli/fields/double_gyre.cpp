#include "stimuli/fields/double_gyre.hpp"

#include <cmath>
#include <numbers>

namespace tlab::stimuli {

glm::dvec3 DoubleGyre::velocity(const glm::dvec3& p, double t) const {
  constexpr double pi = std::numbers::pi;
  const double s = p_.epsilon * std::sin(p_.omega * t);
  const double f = s * p.x * p.x + (1.0 - 2.0 * s) * p.x;
  const double dfdx = 2.0 * s * p.x + 1.0 - 2.0 * s;
  return {-pi * p_.amplitude * std::sin(pi * f) * std::cos(pi * p.y),
          pi * p_.amplitude * std::cos(pi * f) * std::sin(pi * p.y) * dfdx, p_.climb};
}

}  // namespace tlab::stimuli
