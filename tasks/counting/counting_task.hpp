#pragma once
// Elmqvist Sec. 4, T1 "count the number of targets (red objects)" and T4 "count the number of
// targets" of a named type. One question per scene; scored by relative error |answer − truth| /
// truth (Elmqvist Sec. 5), totals by sumOfErrorsOverSumOfTargets (scoring.hpp).
#include "tasks/task.hpp"

namespace tlab::tasks {

class CountingTask : public Task {
 public:
  std::string name() const override { return "counting"; }
  std::string summary() const override { return "the number of targets (Target role, or objects of a kind)"; }
  std::vector<SettingSpec> settingSpecs() const override;
  std::vector<Question> probe(const ProbeRequest& request) const override;
};

// Scene-level tasks ask one question per scene: count must be 1.
void requireOneQuestion(const std::string& task, int count);

}  // namespace tlab::tasks
