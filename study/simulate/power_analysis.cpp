#include "study/simulate/power_analysis.hpp"

#include <filesystem>
#include <map>

#include "study/design/order_permutations.hpp"
#include "study/analyze/study_analysis.hpp"
#include "study/simulate/study_simulation.hpp"
#include "study/store/open_store.hpp"

namespace tlab::study {

std::vector<PowerEntry> powerAnalysis(const Experiment& experiment, StimulusLibrary& stimuli, const PowerOptions& options) {
  std::vector<PowerEntry> entries;
  std::map<std::string, std::size_t> index;
  for (int r = 1; r <= options.replicates; ++r) {
    const auto path = std::filesystem::path(options.workDirectory) / ("replicate-" + std::to_string(r) + ".db");
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
    {
      const auto storeOwner = openStore(path.string());
      Store& store = *storeOwner;
      SimulationOptions sim;
      sim.participants = options.participants;
      sim.observerSeed = mixSeed(experiment.seed, "replicate:" + std::to_string(r));
      sim.tlabVersion = options.tlabVersion;
      const SimulationResult result = simulateStudy(experiment, store, stimuli, sim);
      const StoredExperiment stored = storedExperiment(store, experiment.id);
      for (const auto& analysis : analyzeStudy(store, stored))
        for (const auto& p : analysis.pValues()) {
          auto [it, inserted] = index.emplace(p.name, entries.size());
          if (inserted) entries.push_back({p.name, 0, 0, analysis.spec.alpha});
          entries[it->second].significant += p.p < analysis.spec.alpha ? 1 : 0;
        }
      if (options.progress) options.progress(r, result.seconds);
    }
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
  }
  for (auto& e : entries) e.replicates = options.replicates;
  return entries;
}

}  // namespace tlab::study
