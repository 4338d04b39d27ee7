#pragma once
// Hill's spherical vortex of radius a in the frame moving with it, with swirl (Moffatt 1969):
// inside (R < a), ψ = (3/4) U r² (1 − R²/a²) → v_z = (3U/2)(1 − (2r² + z²)/a²), v_r = (3U/2) r z/a²,
// v_φ = S r (1 − R²/a²); outside, the potential flow past the sphere, ψ = −(1/2) U r² (1 − a³/R³)
// (uniform stream −U far away). r: distance from the axis, R: from the centre.
#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

struct HillsVortexParams {
  double radius = 1.0;  // a
  double speed = 1.0;   // U
  double swirl = 1.5;   // S
};

class HillsSphericalVortex final : public VectorField {
 public:
  explicit HillsSphericalVortex(HillsVortexParams p = {}) : p_(p) {}
  std::string name() const override { return "hills-vortex"; }
  bool steady() const override { return true; }
  FieldDomain domain() const override { return {glm::dvec3(-3.0), glm::dvec3(3.0)}; }
  glm::dvec3 velocity(const glm::dvec3& x, double t) const override;

 private:
  HillsVortexParams p_;
};

}  // namespace tlab::stimuli
