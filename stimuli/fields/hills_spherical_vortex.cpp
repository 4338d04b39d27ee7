#include "stimuli/fields/hills_spherical_vortex.hpp"

#include <cmath>

#include "stimuli/fields/cylindrical_velocity.hpp"

namespace tlab::stimuli {

glm::dvec3 HillsSphericalVortex::velocity(const glm::dvec3& x, double) const {
  const CylindricalPoint c = toCylindrical(x);
  const double a2 = p_.radius * p_.radius, u = p_.speed;
  const double r2 = c.r * c.r, big2 = r2 + c.z * c.z;
  if (big2 < a2) {
    const double vz = 1.5 * u * (1.0 - (2.0 * r2 + c.z * c.z) / a2);
    const double vr = 1.5 * u * c.r * c.z / a2;
    const double vphi = p_.swirl * c.r * (1.0 - big2 / a2);
    return fromCylindrical(c, vr, vphi, vz);
  }
  const double big = std::sqrt(big2), a3 = a2 * p_.radius, big5 = big2 * big2 * big;
  // v_z = (1/r) ∂ψ/∂r, v_r = −(1/r) ∂ψ/∂z with ψ = −(1/2) U r² (1 − a³/R³).
  const double vz = -u * (1.0 - a3 / (big2 * big)) - 1.5 * u * r2 * a3 / big5;
  const double vr = 1.5 * u * c.r * c.z * a3 / big5;
  return fromCylindrical(c, vr, 0.0, vz);
}

}  // namespace tlab::stimuli
