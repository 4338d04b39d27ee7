#include "study/window/gauge_drawing.hpp"

#include <algorithm>
#include <cmath>

namespace tlab::study {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr Rgba kUnder{255, 255, 255, 255}, kOver{200, 30, 30, 255};

// A polyline of dots no more than half a pixel apart.
void dots(Canvas& c, glm::dvec2 a, glm::dvec2 b, double radius, Rgba color) {
  const int steps = std::max(1, int(std::ceil(2.0 * glm::length(b - a))));
  for (int i = 0; i <= steps; ++i) {
    const glm::dvec2 p = glm::mix(a, b, double(i) / steps);
    c.fillCircle(p.x, p.y, radius, color);
  }
}

void shape(Canvas& c, glm::dvec2 centre, double radius, double slant, double tilt, double width, Rgba color) {
  const glm::dvec2 along(std::cos(tilt), -std::sin(tilt)), across(std::sin(tilt), std::cos(tilt));
  glm::dvec2 previous{};
  for (int i = 0; i <= 72; ++i) {
    const double a = 2.0 * kPi * i / 72.0;
    const glm::dvec2 p = centre + radius * std::cos(slant) * std::cos(a) * along + radius * std::sin(a) * across;
    if (i > 0) dots(c, previous, p, width, color);
    previous = p;
  }
  dots(c, centre, centre + radius * std::sin(slant) * along, width, color);
  c.fillCircle(centre.x, centre.y, width + 1.0, color);
}

}  // namespace

void drawGauge(Canvas& canvas, glm::dvec2 centre, double radius, double slantDegrees, double tiltDegrees) {
  const double slant = slantDegrees * kPi / 180.0, tilt = tiltDegrees * kPi / 180.0;
  shape(canvas, centre, radius, slant, tilt, 1.8, kUnder);
  shape(canvas, centre, radius, slant, tilt, 0.9, kOver);
}

glm::dvec2 gaugeToward(glm::dvec2 centre, double radius, glm::dvec2 point) {
  const glm::dvec2 d((point.x - centre.x) / radius, (centre.y - point.y) / radius);
  const double reach = std::min(glm::length(d), std::sin(85.0 * kPi / 180.0));
  double tilt = std::atan2(d.y, d.x) * 180.0 / kPi;
  if (tilt < 0.0) tilt += 360.0;
  return {std::asin(reach) * 180.0 / kPi, glm::length(d) > 0.0 ? tilt : 0.0};
}

}  // namespace tlab::study
