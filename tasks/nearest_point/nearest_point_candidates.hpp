#pragma once
// How NearestPointTask chooses a question's candidates: from a pool of surface points with their
// geodesic distances from A (exact, or proven lower bounds) and Euclidean distances, a
// geodesic-nearest candidate and others all ≥ (1 + margin) × its distance along the surface,
// with or without a Euclidean "trap"; and which points can head a question at all, from upper
// bounds alone (before any exact distance is computed). Internal to tasks/.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/seeded_random.hpp"
#include "tasks/nearest_point/surface_point.hpp"

namespace tlab::tasks::nearest {

struct PoolPoint {
  SurfacePoint where;
  glm::dvec3 world;
  glm::dvec2 pixel;
  double geodesic, euclidean;  // geodesic: exact, or a proven lower bound when !exact
  bool exact;
};

struct Choice {
  std::vector<PoolPoint> candidates;
  double geodesicMargin, euclideanMargin;
  bool trap;
};

// Index of the smallest value.
std::size_t argMin(const std::vector<double>& v);

// Searches the pool (in a seeded random order) for a geodesic-nearest candidate g and others
// that are all ≥ (1 + margin) × d(g) away along the surface; with a trap, one of the others is
// Euclidean-nearest by the same margin, else g is also Euclidean-nearest.
std::optional<Choice> chooseCandidates(std::vector<PoolPoint> pool, int count, double margin, bool wantTrap,
                                       double pixelGap, core::SeededRandom& random);

// The upper bounds U(g) of the points g that can head a question, smallest first: any point
// without a trap; with one, a g for which some e is Euclidean-nearer by the margin while its
// surface distance may still exceed g's by it (U(e) ≥ (1 + m)·E(g), the most optimistic case).
std::vector<double> headBounds(const std::vector<double>& upper, const std::vector<double>& straight, double margin, bool trap);

}  // namespace tlab::tasks::nearest
