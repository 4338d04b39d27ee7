#pragma once
// The seed curve of an integral surface (IRIS Sec. 2): a polyline parameterized by normalized arc
// length s ∈ [0, 1]; s becomes the surface's first parameter.
#include <vector>

#include <glm/glm.hpp>

namespace tlab::stimuli {

class SeedCurve {
 public:
  // At least two points; throws std::invalid_argument otherwise or when the length is zero.
  explicit SeedCurve(std::vector<glm::dvec3> points);
  static SeedCurve line(const glm::dvec3& from, const glm::dvec3& to);
  // A circle of `radius` about `center` in the plane spanned by unit axes u, v (closed: s = 0 and
  // s = 1 meet).
  static SeedCurve circle(const glm::dvec3& center, const glm::dvec3& u, const glm::dvec3& v, double radius, int segments);

  glm::dvec3 at(double s) const;
  double length() const { return cumulative_.back(); }

 private:
  std::vector<glm::dvec3> points_;
  std::vector<double> cumulative_;  // arc length up to each point
};

}  // namespace tlab::stimuli
