#pragma once
// Axisymmetric fields about the z axis are written in cylindrical components (v_r, v_φ, v_z);
// this turns them into Cartesian velocity at x.
#include <cmath>

#include <glm/glm.hpp>

namespace tlab::stimuli {

struct CylindricalPoint {
  double r;    // distance from the z axis
  double z;
  glm::dvec2 radial;  // unit (cos φ, sin φ); (1, 0) on the axis
};

inline CylindricalPoint toCylindrical(const glm::dvec3& x) {
  const double r = std::hypot(x.x, x.y);
  return {r, x.z, r > 0.0 ? glm::dvec2(x.x, x.y) / r : glm::dvec2(1.0, 0.0)};
}

inline glm::dvec3 fromCylindrical(const CylindricalPoint& p, double vr, double vphi, double vz) {
  return {vr * p.radial.x - vphi * p.radial.y, vr * p.radial.y + vphi * p.radial.x, vz};
}

}  // namespace tlab::stimuli
