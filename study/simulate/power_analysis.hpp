#pragma once
// PowerAnalysis: repeats the simulated study R times (fresh observers per replicate, the same
// stimuli) and counts, for every p-value the analysis plan produces, how often it falls below the
// plan's alpha — the simulated power of each planned test at the given number of participants.
#include <functional>
#include <string>
#include <vector>

#include "study/design/experiment.hpp"
#include "study/run/stimulus_library.hpp"

namespace tlab::study {

struct PowerEntry {
  std::string test;  // as PlannedPValue::name
  int significant = 0;
  int replicates = 0;
  double alpha = 0.05;
  double power() const { return replicates ? double(significant) / replicates : 0.0; }
};

struct PowerOptions {
  int replicates = 10;
  int participants = 1;
  std::string workDirectory;  // replicate databases are created (and removed) here
  std::string tlabVersion = "unknown";
  std::function<void(int replicate, double seconds)> progress;
};

std::vector<PowerEntry> powerAnalysis(const Experiment& experiment, StimulusLibrary& stimuli, const PowerOptions& options);

}  // namespace tlab::study
