#include "stimuli/fields/double_gyre.hpp"

#include <cmath>
#include <numbers>

namespace tlab::stimuli {

DoubleGyre::Forcing DoubleGyre::forcing(double x, double t) const {
  const double s = p_.epsilon * std::sin(p_.omega * t), st = p_.epsilon * p_.omega * std::cos(p_.omega * t);
  return {s * x * x + (1.0 - 2.0 * s) * x, 2.0 * s * x + 1.0 - 2.0 * s, 2.0 * s, st * (x * x - 2.0 * x), st * (2.0 * x - 2.0)};
}

glm::dvec3 DoubleGyre::velocity(const glm::dvec3& p, double t) const {
  constexpr double pi = std::numbers::pi;
  const Forcing g = forcing(p.x, t);
  return {-pi * p_.amplitude * std::sin(pi * g.f) * std::cos(pi * p.y), pi * p_.amplitude * std::cos(pi * g.f) * std::sin(pi * p.y) * g.fx,
          p_.climb};
}

glm::dmat3 DoubleGyre::jacobian(const glm::dvec3& p, double t) const {
  constexpr double pi = std::numbers::pi;
  const Forcing g = forcing(p.x, t);
  const double a = p_.amplitude, sf = std::sin(pi * g.f), cf = std::cos(pi * g.f), sy = std::sin(pi * p.y), cy = std::cos(pi * p.y);
  glm::dmat3 j(0.0);
  j[0] = {-pi * pi * a * cf * g.fx * cy, pi * a * (-pi * sf * g.fx * g.fx + cf * g.fxx) * sy, 0.0};  // ∂/∂x
  j[1] = {pi * pi * a * sf * sy, pi * pi * a * cf * cy * g.fx, 0.0};                                  // ∂/∂y
  return j;
}

glm::dvec3 DoubleGyre::timeDerivative(const glm::dvec3& p, double t) const {
  constexpr double pi = std::numbers::pi;
  const Forcing g = forcing(p.x, t);
  const double a = p_.amplitude, sf = std::sin(pi * g.f), cf = std::cos(pi * g.f), sy = std::sin(pi * p.y), cy = std::cos(pi * p.y);
  return {-pi * pi * a * cf * g.ft * cy, pi * a * sy * (-pi * sf * g.ft * g.fx + cf * g.fxt), 0.0};
}

}  // namespace tlab::stimuli
