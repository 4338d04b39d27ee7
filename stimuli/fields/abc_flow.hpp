#pragma once
// The Arnold–Beltrami–Childress flow v = (A sin z + C cos y, B sin x + A cos z, C sin y + B cos x):
// steady, divergence-free, with chaotic stream lines for A = √3, B = √2, C = 1.
#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

class AbcFlow final : public VectorField {
 public:
  AbcFlow(double a = 1.7320508075688772, double b = 1.4142135623730951, double c = 1.0) : a_(a), b_(b), c_(c) {}
  std::string name() const override { return "abc"; }
  bool steady() const override { return true; }
  FieldDomain domain() const override { return {glm::dvec3(-10.0), glm::dvec3(10.0)}; }
  glm::dvec3 velocity(const glm::dvec3& x, double t) const override;
  glm::dmat3 jacobian(const glm::dvec3& x, double t) const override;

 private:
  double a_, b_, c_;
};

}  // namespace tlab::stimuli
