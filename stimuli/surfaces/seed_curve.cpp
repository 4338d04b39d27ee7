#include "stimuli/surfaces/seed_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tlab::stimuli {

SeedCurve::SeedCurve(std::vector<glm::dvec3> points) : points_(std::move(points)) {
  if (points_.size() < 2) throw std::invalid_argument("a seed curve needs at least two points");
  cumulative_.push_back(0.0);
  for (std::size_t i = 1; i < points_.size(); ++i) cumulative_.push_back(cumulative_.back() + glm::distance(points_[i - 1], points_[i]));
  if (!(cumulative_.back() > 0.0)) throw std::invalid_argument("a seed curve must have a positive length");
}

SeedCurve SeedCurve::line(const glm::dvec3& from, const glm::dvec3& to) { return SeedCurve({from, to}); }

SeedCurve SeedCurve::circle(const glm::dvec3& center, const glm::dvec3& u, const glm::dvec3& v, double radius, int segments) {
  std::vector<glm::dvec3> pts;
  for (int i = 0; i <= segments; ++i) {
    const double a = 2.0 * std::numbers::pi * double(i % segments) / double(segments);
    pts.push_back(center + radius * (std::cos(a) * u + std::sin(a) * v));
  }
  return SeedCurve(std::move(pts));
}

glm::dvec3 SeedCurve::at(double s) const {
  const double target = std::clamp(s, 0.0, 1.0) * length();
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
  const std::size_t i = std::min<std::size_t>(std::max<std::ptrdiff_t>(1, it - cumulative_.begin()), points_.size() - 1);
  const double span = cumulative_[i] - cumulative_[i - 1];
  const double f = span > 0.0 ? (target - cumulative_[i - 1]) / span : 0.0;
  return glm::mix(points_[i - 1], points_[i], f);
}

}  // namespace tlab::stimuli
