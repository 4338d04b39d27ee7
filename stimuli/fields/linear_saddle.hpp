#pragma once
// The linear saddle v = (a x, −a y, b z): closed-form trajectories x(t) = (x0 e^{a t}, y0 e^{−a t},
// z0 e^{b t}); exponential growth makes error control matter.
#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

class LinearSaddle final : public VectorField {
 public:
  explicit LinearSaddle(double a = 1.0, double b = -0.5) : a_(a), b_(b) {}
  std::string name() const override { return "linear-saddle"; }
  bool steady() const override { return true; }
  FieldDomain domain() const override { return {glm::dvec3(-1e6), glm::dvec3(1e6)}; }
  glm::dvec3 velocity(const glm::dvec3& x, double t) const override;
  glm::dmat3 jacobian(const glm::dvec3& x, double t) const override;
  glm::dvec3 exactPosition(const glm::dvec3& x0, double t0, double t1) const;

 private:
  double a_, b_;
};

}  // namespace tlab::stimuli
