#pragma once
// StudySimulation: the whole study with SimulatedObservers instead of people — participants
// "sim-001" … "sim-N" (or from sim-<first>) run one after the other through the same TrialRunner (same plan, stimuli,
// scoring and database writes as a window session). With `resume`, finished simulated
// participants are skipped and an interrupted one continues at its first unanswered trial.
#include <cstdint>
#include <functional>
#include <string>

#include "study/design/experiment.hpp"
#include "study/store/store.hpp"
#include "study/run/stimulus_library.hpp"
#include "study/run/trial_runner.hpp"

namespace tlab::study {

struct SimulationOptions {
  int participants = 1;
  int firstParticipant = 1;         // sim-<first> … sim-<first+participants-1> (two stations: disjoint ranges)
  bool resume = false;
  double paceSeconds = 0.0;         // real seconds slept per simulated second
  std::uint64_t observerSeed = 0;   // seeds the observers (power analysis: one per replicate)
  std::string tlabVersion = "unknown";
  std::optional<DisplayInfo> renderer;  // the headless GL that rendered the stimuli (stored with each session)
  std::function<void(const std::string&)> log;        // participant-level lines
  std::function<void(const TrialProgress&)> progress;  // after each committed response
};

struct SimulationResult {
  int participantsRun = 0;
  int trialsAnswered = 0;
  double seconds = 0.0;  // wall time
};

std::string simulatedParticipantId(int index);  // 1-based: "sim-001"

SimulationResult simulateStudy(const Experiment& experiment, Store& store, StimulusLibrary& stimuli,
                               const SimulationOptions& options);

}  // namespace tlab::study
