#include "stimuli/fields/abc_flow.hpp"

#include <cmath>

namespace tlab::stimuli {

glm::dvec3 AbcFlow::velocity(const glm::dvec3& p, double) const {
  return {a_ * std::sin(p.z) + c_ * std::cos(p.y), b_ * std::sin(p.x) + a_ * std::cos(p.z),
          c_ * std::sin(p.y) + b_ * std::cos(p.x)};
}

glm::dmat3 AbcFlow::jacobian(const glm::dvec3& p, double) const {
  glm::dmat3 j(0.0);
  j[0] = {0.0, b_ * std::cos(p.x), -b_ * std::sin(p.x)};
  j[1] = {-c_ * std::sin(p.y), 0.0, c_ * std::cos(p.y)};
  j[2] = {a_ * std::cos(p.z), -a_ * std::sin(p.z), 0.0};
  return j;
}

}  // namespace tlab::stimuli
