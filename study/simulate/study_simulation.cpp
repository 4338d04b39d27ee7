#include "study/simulate/study_simulation.hpp"

#include <chrono>
#include <cstdio>

#include "study/run/simulated_observer.hpp"

namespace tlab::study {

std::string simulatedParticipantId(int index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "sim-%03d", index);
  return buf;
}

SimulationResult simulateStudy(const Experiment& experiment, Store& store, StimulusLibrary& stimuli,
                               const SimulationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  TrialRunner runner(experiment, store, stimuli);
  if (options.progress) runner.onProgress(options.progress);
  SimulationResult result;
  for (int i = options.firstParticipant; i < options.firstParticipant + options.participants; ++i) {
    const std::string id = simulatedParticipantId(i);
    const auto existing = store.findParticipant(experiment.id, id);
    if (existing && !options.resume)
      throw StoreError(store.location() + " already holds simulated participant '" + id +
                       "'; continue with --resume or use a new database");
    if (existing && existing->status != "active") continue;
    SimulatedObserver observer(experiment.observer, options.observerSeed, id, options.paceSeconds);
    observer.setRenderer(options.renderer);
    const SessionResult r = runner.run({id, existing.has_value(), options.tlabVersion}, observer);
    result.participantsRun += 1;
    result.trialsAnswered += r.answeredNow;
    if (options.log) {
      char line[160];
      std::snprintf(line, sizeof line, "participant %s: slot %d, %d trials%s, skill %.3f", id.c_str(), r.slot, r.total,
                    r.answeredBefore ? (" (resumed after " + std::to_string(r.answeredBefore) + ")").c_str() : "", observer.skill());
      options.log(line);
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace tlab::study
