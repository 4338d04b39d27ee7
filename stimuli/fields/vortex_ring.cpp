#include "stimuli/fields/vortex_ring.hpp"

#include <cmath>
#include <numbers>

#include "stimuli/fields/cylindrical_velocity.hpp"

namespace tlab::stimuli {

glm::dvec3 VortexRing::velocity(const glm::dvec3& x, double) const {
  const CylindricalPoint c = toCylindrical(x);
  const double dr = c.r - p_.ringRadius, dz = c.z;
  const double a2 = p_.coreRadius * p_.coreRadius;
  const double gaussian = std::exp(-(dr * dr + dz * dz) / a2);
  // ψ = (r²/2) G(ρ²), G(q) = c a² (1 − e^{−q/a²}), c = Ω/R with the core's angular speed
  // Ω = Γ/(2π a²) (Lamb–Oseen): v_r = −r G' dz, v_z = G + r G' dr, G' = c e^{−ρ²/a²}.
  const double omega = p_.circulation / (2.0 * std::numbers::pi * a2);
  const double cc = omega / p_.ringRadius;
  const double g1 = cc * gaussian;
  const double vr = -c.r * g1 * dz;
  const double vz = cc * a2 * (1.0 - gaussian) + c.r * g1 * dr + p_.travelSpeed;
  const double vphi = p_.swirl * gaussian;
  return fromCylindrical(c, vr, vphi, vz);
}

}  // namespace tlab::stimuli
