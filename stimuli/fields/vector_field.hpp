#pragma once
// A 3-D vector field v(x, t) (IRIS Sec. 2: the flow whose integral curves sweep stream and path
// surfaces), with its Jacobian ∂v/∂x and ∂v/∂t for implicit integrators (Rosenbrock4).
#include <string>

#include <glm/glm.hpp>

namespace tlab::stimuli {

// An axis-aligned box: where a field is defined and where particles stop.
struct FieldDomain {
  glm::dvec3 lower{-1.0};
  glm::dvec3 upper{1.0};
  bool contains(const glm::dvec3& x) const {
    return glm::all(glm::greaterThanEqual(x, lower)) && glm::all(glm::lessThanEqual(x, upper));
  }
};

class VectorField {
 public:
  virtual ~VectorField() = default;
  virtual std::string name() const = 0;
  // True when v does not depend on t (stream lines = path lines).
  virtual bool steady() const = 0;
  virtual FieldDomain domain() const = 0;
  virtual glm::dvec3 velocity(const glm::dvec3& x, double t) const = 0;
  // J = ∂v/∂x with J[j] = ∂v/∂x_j (glm column j). Default: central differences.
  virtual glm::dmat3 jacobian(const glm::dvec3& x, double t) const;
  // ∂v/∂t. Default: zero for steady fields, else central differences.
  virtual glm::dvec3 timeDerivative(const glm::dvec3& x, double t) const;
};

// The field frozen at time t0: the stream lines of an unsteady field at one instant (IRIS Sec. 2:
// stream surfaces use v(·, t0), path surfaces use v(·, t)).
class FrozenTimeField final : public VectorField {
 public:
  FrozenTimeField(const VectorField& field, double t0) : field_(field), t0_(t0) {}
  std::string name() const override { return field_.name() + "@t0"; }
  bool steady() const override { return true; }
  FieldDomain domain() const override { return field_.domain(); }
  glm::dvec3 velocity(const glm::dvec3& x, double) const override { return field_.velocity(x, t0_); }
  glm::dmat3 jacobian(const glm::dvec3& x, double) const override { return field_.jacobian(x, t0_); }
  glm::dvec3 timeDerivative(const glm::dvec3&, double) const override { return glm::dvec3(0.0); }

 private:
  const VectorField& field_;
  double t0_;
};

}  // namespace tlab::stimuli
