#include "tasks/gauge_frame.hpp"

#include <cmath>
#include <stdexcept>

namespace tlab::tasks {

namespace {
constexpr double kPi = 3.14159265358979323846;
double radians(double d) { return d * kPi / 180.0; }
double degrees(double r) { return r * 180.0 / kPi; }

glm::dvec3 direction(const Question& q, const std::string& name) {
  for (const auto& [key, d] : q.directions)
    if (key == name) return d;
  throw std::invalid_argument(q.task + ": the question keeps no '" + name + "' direction");
}
}  // namespace

GaugeFrame gaugeFrame(const ViewGeometry& view, glm::dvec3 point) {
  GaugeFrame f;
  f.w = glm::normalize(view.eye() - point);
  const glm::dvec3 right = view.right();
  f.u = glm::normalize(right - f.w * glm::dot(right, f.w));
  f.v = glm::cross(f.w, f.u);
  return f;
}

GaugeFrame gaugeFrameOf(const Question& q) { return {direction(q, "right"), direction(q, "up"), direction(q, "toward-eye")}; }

void keepGaugeFrame(Question& q, const GaugeFrame& f) { q.directions = {{"right", f.u}, {"up", f.v}, {"toward-eye", f.w}}; }

glm::dvec3 normalFromSlantTilt(const GaugeFrame& f, double slantDegrees, double tiltDegrees) {
  const double s = radians(slantDegrees), t = radians(tiltDegrees);
  return std::sin(s) * std::cos(t) * f.u + std::sin(s) * std::sin(t) * f.v + std::cos(s) * f.w;
}

glm::dvec2 slantTiltOf(const GaugeFrame& f, glm::dvec3 n) {
  n = glm::normalize(n);
  const double x = glm::dot(n, f.u), y = glm::dot(n, f.v), z = glm::dot(n, f.w);
  const double slant = degrees(std::atan2(std::hypot(x, y), z));
  double tilt = degrees(std::atan2(y, x));
  if (tilt < 0.0) tilt += 360.0;
  if (tilt >= 360.0) tilt -= 360.0;
  return {slant, tilt};
}

double angleDegrees(glm::dvec3 a, glm::dvec3 b) {
  a = glm::normalize(a);
  b = glm::normalize(b);
  // atan2 of |a × b| and a·b: exact for small and large angles alike (acos loses digits near 0).
  return degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

double tiltDifference(double a, double b) {
  double d = std::fmod(a - b + 180.0, 360.0);
  if (d < 0.0) d += 360.0;
  return d - 180.0;
}

}  // namespace tlab::tasks
