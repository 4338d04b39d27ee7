#include "stimuli/integration/particle_integrator.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include <boost/numeric/odeint.hpp>
#include <boost/numeric/ublas/matrix.hpp>
#include <boost/numeric/ublas/vector.hpp>

namespace tlab::stimuli {

namespace odeint = boost::numeric::odeint;
namespace ublas = boost::numeric::ublas;

std::string integratorName(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::RungeKutta4: return "rk4";
    case IntegratorKind::DormandPrince: return "dopri5";
    case IntegratorKind::Rosenbrock4: return "rosenbrock4";
  }
  return "?";
}

IntegratorKind parseIntegratorKind(const std::string& name) {
  if (name == "rk4") return IntegratorKind::RungeKutta4;
  if (name == "dopri5") return IntegratorKind::DormandPrince;
  if (name == "rosenbrock4") return IntegratorKind::Rosenbrock4;
  throw std::invalid_argument("unknown integrator '" + name + "' (known: rk4, dopri5, rosenbrock4)");
}

namespace {

using ArrayState = std::array<double, 3>;
using UblasState = ublas::vector<double>;

glm::dvec3 toGlm(const ArrayState& s) { return {s[0], s[1], s[2]}; }
glm::dvec3 toGlm(const UblasState& s) { return {s[0], s[1], s[2]}; }

// dx/dt = v(x, t) in odeint's system signature.
struct ArraySystem {
  const VectorField& field;
  void operator()(const ArrayState& x, ArrayState& dxdt, double t) const {
    const glm::dvec3 v = field.velocity(toGlm(x), t);
    dxdt = {v.x, v.y, v.z};
  }
};

// Rosenbrock4 integrates the autonomous system (x, τ)' = (v(x, τ), 1): the time derivative ∂v/∂t
// becomes the Jacobian's fourth column. (Passing ∂v/∂t through odeint's dfdt argument instead gave
// errors of 5e-4 at tolerance 1e-8 on v = (cos t, x, 0) with Boost 1.74 — the case in
// particle_integrator_test.cpp — while the autonomous form meets the tolerance.)
struct UblasSystem {
  const VectorField& field;
  void operator()(const UblasState& x, UblasState& dxdt, double) const {
    const glm::dvec3 v = field.velocity(toGlm(x), x[3]);
    for (int i = 0; i < 3; ++i) dxdt[i] = v[i];
    dxdt[3] = 1.0;
  }
};

struct UblasJacobian {
  const VectorField& field;
  void operator()(const UblasState& x, ublas::matrix<double>& jac, double, UblasState& dfdt) const {
    const glm::dvec3 p = toGlm(x);
    const glm::dmat3 j = field.jacobian(p, x[3]);
    const glm::dvec3 dt = field.timeDerivative(p, x[3]);
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col) jac(row, col) = 0.0;
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) jac(row, col) = j[col][row];
      jac(row, 3) = dt[row];
    }
    for (int i = 0; i < 4; ++i) dfdt[i] = 0.0;
  }
};

ParticleAdvance advanceRk4(const VectorField& field, const glm::dvec3& x0, double t0, double t1, double step) {
  ArrayState x{x0.x, x0.y, x0.z};
  const double span = t1 - t0;
  const std::size_t n = std::max<std::size_t>(1, std::size_t(std::ceil(std::abs(span) / step - 1e-9)));
  const double h = span / double(n);
  odeint::runge_kutta4<ArrayState> stepper;
  odeint::integrate_n_steps(stepper, ArraySystem{field}, x, t0, h, n);  // returns the end time
  return {toGlm(x), n};
}

ParticleAdvance advanceDopri5(const VectorField& field, const glm::dvec3& x0, double t0, double t1,
                              const IntegratorSettings& s) {
  ArrayState x{x0.x, x0.y, x0.z};
  auto stepper = odeint::make_dense_output(s.absoluteTolerance, s.relativeTolerance, odeint::runge_kutta_dopri5<ArrayState>());
  const double dt = t1 >= t0 ? s.step : -s.step;
  const std::size_t steps = odeint::integrate_adaptive(stepper, ArraySystem{field}, x, t0, t1, dt);
  return {toGlm(x), steps};
}

ParticleAdvance advanceRosenbrock4(const VectorField& field, const glm::dvec3& x0, double t0, double t1,
                                   const IntegratorSettings& s) {
  UblasState x(4);
  for (int i = 0; i < 3; ++i) x[i] = x0[i];
  x[3] = t0;
  auto stepper = odeint::make_dense_output(s.absoluteTolerance, s.relativeTolerance, odeint::rosenbrock4<double>());
  const double dt = t1 >= t0 ? s.step : -s.step;
  const std::size_t steps =
      odeint::integrate_adaptive(stepper, std::make_pair(UblasSystem{field}, UblasJacobian{field}), x, t0, t1, dt);
  return {toGlm(x), steps};
}

}  // namespace

ParticleAdvance ParticleIntegrator::advance(const glm::dvec3& x0, double t0, double t1) const {
  if (t1 == t0) return {x0, 0};
  switch (settings_.kind) {
    case IntegratorKind::RungeKutta4: return advanceRk4(field_, x0, t0, t1, settings_.step);
    case IntegratorKind::DormandPrince: return advanceDopri5(field_, x0, t0, t1, settings_);
    case IntegratorKind::Rosenbrock4: return advanceRosenbrock4(field_, x0, t0, t1, settings_);
  }
  throw std::logic_error("unknown integrator kind");
}

}  // namespace tlab::stimuli
