#pragma once
// The shortest way between two points of one boundary loop (Carnecky Sec. 8.1, Task 2 "follow
// the shortest path on the boundary of the surface"), by 3-D arc length, and which marks it meets.
namespace tlab::tasks {

struct BoundaryArc {
  double from = 0.0;       // arc position of the start, in [0, loopLength)
  double length = 0.0;     // arc length travelled
  int direction = 1;       // +1: increasing arc position, −1: decreasing
  double loopLength = 0.0;

  // True when arc position `arc` lies strictly inside the way (ends excluded).
  bool contains(double arc) const;
  // Arc length travelled from the start to `arc` going this way, in [0, loopLength).
  double travelled(double arc) const;
};

// Arc length from a to b going forward (increasing arc), in [0, loopLength).
double forwardArcLength(double a, double b, double loopLength);

// The shorter of the two ways from a to b (forward on a tie).
BoundaryArc shortestBoundaryArc(double a, double b, double loopLength);

}  // namespace tlab::tasks
