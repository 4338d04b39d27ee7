#pragma once
// The boundary loops of a welded mesh: closed polylines of the edges used by one triangle
// (Carnecky Fig. 2, red lines), parameterised by 3-D arc length.
#include <vector>

#include <glm/glm.hpp>

#include "tasks/welded_mesh.hpp"

namespace tlab::tasks {

class BoundaryLoop {
 public:
  BoundaryLoop(std::vector<glm::dvec3> points, int object);

  int object() const { return object_; }
  const std::vector<glm::dvec3>& points() const { return points_; }  // closed: last joins first
  double length() const { return arc_.back(); }
  // The point at arc length `arc` from points()[0] in the loop's direction (wrapped to the loop).
  glm::dvec3 pointAt(double arc) const;
  // Wraps any arc length into [0, length()).
  double wrap(double arc) const;

 private:
  std::vector<glm::dvec3> points_;
  std::vector<double> arc_;  // arc_[i] = arc length at points_[i]; arc_[n] = length
  int object_;
};

// Loops follow the boundary edges in the direction of their triangles' winding. A vertex where
// several loops touch is left by the first unused boundary edge, so every edge is in one loop.
std::vector<BoundaryLoop> boundaryLoops(const WeldedMesh& mesh, int object);

}  // namespace tlab::tasks
