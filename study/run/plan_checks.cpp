#include "study/run/plan_checks.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>

#include "study/design/experiment_file.hpp"
#include "study/design/session_plan.hpp"
#include "study/run/trial_runner.hpp"

namespace tlab::study {

std::string TrainingShownInTest::message() const {
  return "training trial " + std::to_string(training->sequence) + " (" + training->taskId + ") would show the stimulus of test trial " +
         std::to_string(test->sequence) + ": give training other scenes ({trial} in the scene) or more questions";
}

namespace {
// What a trial shows: its picture, and the question's points, which a front end may draw over it
// (a gauge figure on an unmarked picture: the same picture with the gauge elsewhere is another question).
std::string shown(const TrialRecord& r) {
  const auto question = nlohmann::json::parse(r.questionJson, nullptr, false);
  return r.stimulusSha256 + (question.is_object() && question.contains("points") ? question["points"].dump() : "");
}
}  // namespace

std::optional<TrainingShownInTest> trainingShownInTest(const std::vector<TrialRecord>& records) {
  std::map<std::string, const TrialRecord*> test;
  for (const auto& r : records)
    if (r.phase == "test") test.emplace(shown(r), &r);
  for (const auto& r : records)
    if (r.phase == "training")
      if (const auto found = test.find(shown(r)); found != test.end()) return TrainingShownInTest{&r, found->second};
  return std::nullopt;
}

int slotsOfOneCycle(const Design& design, int participants) {
  return int(std::min<std::size_t>(std::size_t(std::max(participants, 1)), design.balancedMultiple()));
}

std::size_t plannedTrialCount(const Experiment& experiment, const Design& design, int slots) {
  std::size_t count = 0;
  for (int slot = 0; slot < slots; ++slot) count += makeSessionPlan(experiment, design, slot).trials.size();
  return count;
}

namespace {

// The task of a planned trial (its settingsSource and trainingSource name the fields to change).
const TaskSpec& taskOf(const Experiment& experiment, const std::string& taskId) {
  const TaskSpec* task = experiment.task(taskId);
  if (!task) throw ExperimentFileError(experiment.path + ": no task '" + taskId + "'");
  return *task;
}

}  // namespace

void checkPreparedPlans(const Experiment& experiment, const Design& design, StimulusSource& stimuli, int slots,
                        const std::function<void()>& advance) {
  for (int slot = 0; slot < slots; ++slot) {
    const SessionPlan plan = makeSessionPlan(experiment, design, slot);
    std::vector<TrialRecord> records;
    for (const auto& p : plan.trials) {
      try {
        records.push_back(makeTrialRecord(p, stimuli.prepare(p)));
      } catch (const std::exception& e) {
        throw ExperimentFileError(taskOf(experiment, p.taskId).settingsSource + ": " + e.what() + " (" + design.describe(plan.design.blocks[std::size_t(p.block - 1)]) +
                                  ", " + phaseName(p.phase) + " trial " + std::to_string(p.trial) + ")");
      }
      if (advance) advance();
    }
    if (const auto clash = trainingShownInTest(records))
      throw ExperimentFileError(taskOf(experiment, clash->training->taskId).trainingSource + ": slot " + std::to_string(slot) + ": " +
                                clash->message());
  }
}

}  // namespace tlab::study
