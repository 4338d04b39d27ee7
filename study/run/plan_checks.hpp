#pragma once
// The checks of a session plan that need its stimuli prepared: every trial's questions can be
// probed (a task setting no probe can meet fails here), and no training trial shows the stimulus
// of a test trial (a participant would learn its answer). TrialRunner runs them on the plan of
// each newcomer; `tlab design` runs them on every slot of one balanced cycle before anyone takes
// part, failing with the file:line of the field to change.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "study/design/counterbalancing.hpp"
#include "study/design/experiment.hpp"
#include "study/run/stimulus_source.hpp"
#include "study/store/store.hpp"

namespace tlab::study {

// A training trial of `records` whose stimulus (by SHA-256) a test trial shows too.
struct TrainingShownInTest {
  const TrialRecord* training = nullptr;
  const TrialRecord* test = nullptr;
  std::string message() const;  // "training trial 9 (T3) would show the stimulus of test trial 10: ..."
};
std::optional<TrainingShownInTest> trainingShownInTest(const std::vector<TrialRecord>& records);

// One balanced cycle of slots (every design row and between cell once), at most `participants`:
// the slots `tlab design` checks and `tlab serve` prepares.
int slotsOfOneCycle(const Design& design, int participants);

// The number of planned trials of those slots (for a progress bar).
std::size_t plannedTrialCount(const Experiment& experiment, const Design& design, int slots);

// Prepares every trial of slots 0..slots-1 through `stimuli` and checks them as above; `advance`
// is called once per trial. Throws ExperimentFileError "file:line: tasks[N].FIELD: message".
void checkPreparedPlans(const Experiment& experiment, const Design& design, StimulusSource& stimuli, int slots,
                        const std::function<void()>& advance);

}  // namespace tlab::study
