#pragma once
// Elmqvist Sec. 4, T2 "identify pattern formed by the targets (red cones)": the targets' floor
// positions form one of the letters C, K, R, X, Y (letter_patterns.hpp), rotated about the
// vertical axis; the ground truth is the one letter they match; scored correct/incorrect.
#include "tasks/task.hpp"

namespace tlab::tasks {

class PatternTask : public Task {
 public:
  std::string name() const override { return "pattern"; }
  std::string summary() const override { return "the letter (C, K, R, X, Y) formed by the targets on the floor plan"; }
  std::vector<SettingSpec> settingSpecs() const override;
  std::vector<Question> probe(const ProbeRequest& request) const override;
};

}  // namespace tlab::tasks
