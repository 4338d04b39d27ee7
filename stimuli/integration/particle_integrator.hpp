#pragma once
// Particle integration through Boost.Odeint (IRIS Sec. 2: path lines dx/dt = v(x, t)):
// fixed-step classical Runge–Kutta 4, adaptive Dormand–Prince 5(4) with dense output, and the
// linearly implicit Rosenbrock4 (needs ∂v/∂x and ∂v/∂t) for stiff fields.
#include <cstddef>
#include <string>

#include <glm/glm.hpp>

#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

enum class IntegratorKind { RungeKutta4, DormandPrince, Rosenbrock4 };

std::string integratorName(IntegratorKind kind);  // "rk4", "dopri5", "rosenbrock4"
IntegratorKind parseIntegratorKind(const std::string& name);  // throws std::invalid_argument

struct IntegratorSettings {
  IntegratorKind kind = IntegratorKind::DormandPrince;
  double step = 1e-2;             // RK4: the fixed step (shortened to end exactly on t1); adaptive: the first trial step
  double absoluteTolerance = 1e-6;
  double relativeTolerance = 1e-6;
};

struct ParticleAdvance {
  glm::dvec3 position{0.0};
  std::size_t steps = 0;  // integrator steps taken (accepted steps for the adaptive methods)
};

class ParticleIntegrator {
 public:
  ParticleIntegrator(const VectorField& field, IntegratorSettings settings) : field_(field), settings_(settings) {}
  const IntegratorSettings& settings() const { return settings_; }
  const VectorField& field() const { return field_; }
  // The particle at x0 at time t0, moved to time t1 (t1 may be < t0: backward integration).
  ParticleAdvance advance(const glm::dvec3& x0, double t0, double t1) const;

 private:
  const VectorField& field_;
  IntegratorSettings settings_;
};

}  // namespace tlab::stimuli
