#include "stimuli/fields/vector_field.hpp"

#include <algorithm>
#include <cmath>

namespace tlab::stimuli {

namespace {
// Step for central differences, relative to the magnitude of the coordinate.
double differenceStep(double value) { return 1e-6 * std::max(1.0, std::abs(value)); }
}  // namespace

glm::dmat3 VectorField::jacobian(const glm::dvec3& x, double t) const {
  glm::dmat3 j(0.0);
  for (int k = 0; k < 3; ++k) {
    const double h = differenceStep(x[k]);
    glm::dvec3 plus = x, minus = x;
    plus[k] += h;
    minus[k] -= h;
    j[k] = (velocity(plus, t) - velocity(minus, t)) / (2.0 * h);
  }
  return j;
}

glm::dvec3 VectorField::timeDerivative(const glm::dvec3& x, double t) const {
  if (steady()) return glm::dvec3(0.0);
  const double h = differenceStep(t);
  return (velocity(x, t + h) - velocity(x, t - h)) / (2.0 * h);
}

}  // namespace tlab::stimuli
