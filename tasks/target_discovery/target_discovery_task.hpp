#pragma once
// Elmqvist Sec. 4, T3 "find the unique target ... mark its location on a 2D floor plan": the answer
// is a floor-plan point (world x, z); the score's error is the error distance in world units
// (Elmqvist Sec. 5); it counts as correct within `correct-within`.
#include "tasks/task.hpp"

namespace tlab::tasks {

class TargetDiscoveryTask : public Task {
 public:
  std::string name() const override { return "target-discovery"; }
  std::string summary() const override { return "the floor-plan position of the unique target"; }
  std::vector<SettingSpec> settingSpecs() const override;
  std::vector<Question> probe(const ProbeRequest& request) const override;
};

}  // namespace tlab::tasks
