#pragma once
// Carnecky Sec. 8.1, Task 2 "follow the boundary": "follow the shortest path on the boundary of the
// surface from a given start point to a given end point ... mark all other points encountered on
// the way". Start A and end B lie on one boundary loop; the way is the shorter arc (3-D arc
// length), which must be shorter than the other arc by a margin; marks lie on boundaries, some on
// the way and some off it; the ground truth is the set of marks on the way.
#include "tasks/task.hpp"

namespace tlab::tasks {

class FollowBoundaryTask : public Task {
 public:
  std::string name() const override { return "follow-boundary"; }
  std::string summary() const override { return "the marks met on the shortest way along the boundary from A to B"; }
  std::vector<SettingSpec> settingSpecs() const override;
  std::vector<Question> probe(const ProbeRequest& request) const override;
};

}  // namespace tlab::tasks
