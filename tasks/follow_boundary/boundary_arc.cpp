#include "tasks/follow_boundary/boundary_arc.hpp"

#include <cmath>

namespace tlab::tasks {

double forwardArcLength(double a, double b, double loopLength) {
  const double d = std::fmod(b - a, loopLength);
  return d < 0.0 ? d + loopLength : d;
}

BoundaryArc shortestBoundaryArc(double a, double b, double loopLength) {
  const double forward = forwardArcLength(a, b, loopLength);
  const double backward = forwardArcLength(b, a, loopLength);
  BoundaryArc arc;
  arc.from = forwardArcLength(0.0, a, loopLength);
  arc.loopLength = loopLength;
  arc.direction = forward <= backward ? 1 : -1;
  arc.length = forward <= backward ? forward : backward;
  return arc;
}

double BoundaryArc::travelled(double arc) const {
  return direction > 0 ? forwardArcLength(from, arc, loopLength) : forwardArcLength(arc, from, loopLength);
}

bool BoundaryArc::contains(double arc) const {
  const double t = travelled(arc);
  return t > 0.0 && t < length;
}

}  // namespace tlab::tasks
