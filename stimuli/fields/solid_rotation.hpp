#pragma once
// Rigid rotation about the z axis, v = ω ẑ × x: closed-form trajectories x(t) = R_z(ω t) x0, the
// first reference of `tlab bench integrate` and of the integrator tests.
#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

class SolidRotation final : public VectorField {
 public:
  explicit SolidRotation(double omega = 1.0) : omega_(omega) {}
  std::string name() const override { return "solid-rotation"; }
  bool steady() const override { return true; }
  FieldDomain domain() const override { return {glm::dvec3(-10.0), glm::dvec3(10.0)}; }
  glm::dvec3 velocity(const glm::dvec3& x, double t) const override;
  glm::dmat3 jacobian(const glm::dvec3& x, double t) const override;
  // The exact position at time t1 of the particle at x0 at time t0.
  glm::dvec3 exactPosition(const glm::dvec3& x0, double t0, double t1) const;

 private:
  double omega_;
};

}  // namespace tlab::stimuli
