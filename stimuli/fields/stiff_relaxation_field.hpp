#pragma once
// A stiff field: slow rotation about z (rate ω) and fast relaxation of z onto the slow manifold
// z = g(x, y) = κ x y (rate λ):
//   ẋ = −ω y,  ẏ = ω x,  ż = −λ (z − g) + ∇g · (ẋ, ẏ).
// The Jacobian's eigenvalues are ±iω and −λ: stiffness ratio λ/ω (default 10⁴). Closed form:
// (x, y) rotate rigidly and z(t) = g(x(t), y(t)) + (z0 − g0) e^{−λ (t − t0)}.
#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

class StiffRelaxationField final : public VectorField {
 public:
  explicit StiffRelaxationField(double lambda = 1e4, double omega = 1.0, double kappa = 0.5)
      : lambda_(lambda), omega_(omega), kappa_(kappa) {}
  std::string name() const override { return "stiff-relaxation"; }
  bool steady() const override { return true; }
  FieldDomain domain() const override { return {glm::dvec3(-10.0), glm::dvec3(10.0)}; }
  glm::dvec3 velocity(const glm::dvec3& x, double t) const override;
  glm::dmat3 jacobian(const glm::dvec3& x, double t) const override;
  glm::dvec3 exactPosition(const glm::dvec3& x0, double t0, double t1) const;
  double stiffnessRatio() const { return lambda_ / omega_; }

 private:
  double manifold(double x, double y) const { return kappa_ * x * y; }
  double lambda_, omega_, kappa_;
};

}  // namespace tlab::stimuli
