#pragma once
// Carnecky Sec. 8.1, Task 3 "nearest point": "specify which point is geodesically closest to
// another given point". Distances are exact geodesics on the surface (GeodesicDistances). The
// candidates are chosen so that the geodesically nearest is unique by a margin (second nearest
// ≥ (1 + margin) × nearest), and in a settable share of the questions the Euclidean-nearest
// candidate is another one (itself nearest by the same margin in 3-D) — the questions that test
// surface understanding rather than 3-D proximity.
#include "tasks/task.hpp"

namespace tlab::tasks {

class NearestPointTask : public Task {
 public:
  std::string name() const override { return "nearest-point"; }
  std::string summary() const override { return "the candidate geodesically nearest to A on the surface"; }
  std::vector<SettingSpec> settingSpecs() const override;
  std::vector<Question> probe(const ProbeRequest& request) const override;
};

// Whether question k (0-based) of a set must have a Euclidean-nearest candidate different from
// the geodesic-nearest: spreads round(share × count) such questions evenly and keeps the choice
// of question k independent of the count (so question k is reproducible).
bool wantsEuclideanTrap(int k, double share);

}  // namespace tlab::tasks
