#pragma once
// ExperimentFile: reads and validates an experiment file (TOML). Every error is one line naming
// the file, the line and the field: "study.toml:12: tasks[2].trials: must be >= 1".
// Scenes and styles are not checked here (a stimulus set may add scenes later); tasks, task
// settings, factor references and the design's constraints are.
#include <stdexcept>
#include <string>

#include "study/experiment.hpp"

namespace tlab::study {

class ExperimentFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads `path`. Throws ExperimentFileError.
Experiment readExperimentFile(const std::string& path);
// Parses experiment text; `path` names it in messages.
Experiment parseExperiment(const std::string& text, const std::string& path);

}  // namespace tlab::study
