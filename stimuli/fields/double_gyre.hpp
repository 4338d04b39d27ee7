#pragma once
// The time-dependent double gyre (Shadden et al. 2005) on [0, 2] × [0, 1], extruded in time: the
// third coordinate advances with the clock (ż = c), so path lines are the space-time curves
// (x(t), y(t), c t) and path surfaces sweep the gyres' stretching and folding.
//   ψ = A sin(π f(x, t)) sin(π y),  f = ε sin(ω t) x² + (1 − 2ε sin(ω t)) x,
//   u = −∂ψ/∂y = −π A sin(π f) cos(π y),  v = ∂ψ/∂x = π A cos(π f) sin(π y) ∂f/∂x.
#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

struct DoubleGyreParams {
  double amplitude = 0.1;   // A
  double epsilon = 0.25;    // ε
  double omega = 0.6283185307179586;  // ω = 2π/10
  double climb = 0.1;       // c
};

class DoubleGyre final : public VectorField {
 public:
  explicit DoubleGyre(DoubleGyreParams p = {}) : p_(p) {}
  std::string name() const override { return "double-gyre"; }
  bool steady() const override { return false; }
  FieldDomain domain() const override { return {glm::dvec3(0.0, 0.0, -100.0), glm::dvec3(2.0, 1.0, 100.0)}; }
  glm::dvec3 velocity(const glm::dvec3& x, double t) const override;
  glm::dmat3 jacobian(const glm::dvec3& x, double t) const override;
  glm::dvec3 timeDerivative(const glm::dvec3& x, double t) const override;

 private:
  struct Forcing {
    double f, fx, fxx, ft, fxt;  // f(x, t) and its partial derivatives
  };
  Forcing forcing(double x, double t) const;
  DoubleGyreParams p_;
};

}  // namespace tlab::stimuli
