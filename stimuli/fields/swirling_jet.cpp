#include "stimuli/fields/swirling_jet.hpp"

#include <cmath>

#include "stimuli/fields/cylindrical_velocity.hpp"

namespace tlab::stimuli {

glm::dvec3 SwirlingJet::velocity(const glm::dvec3& x, double) const {
  const CylindricalPoint c = toCylindrical(x);
  const double s2 = p_.bubbleWidth * p_.bubbleWidth;
  const double dz = c.z - p_.bubbleCenter;
  const double e = p_.bubbleStrength * std::exp(-(c.r * c.r + dz * dz) / s2);
  const double vr = -c.r * e * dz / s2;                          // −(1/r) ∂ψ/∂z
  const double vz = p_.axialSpeed - e + e * c.r * c.r / s2;     // (1/r) ∂ψ/∂r
  const double vphi = p_.swirl * c.r * std::exp(-c.r * c.r / (p_.swirlWidth * p_.swirlWidth));
  return fromCylindrical(c, vr, vphi, vz);
}

}  // namespace tlab::stimuli
