#pragma once
// ExperimentFile: reads and validates an experiment file (TOML). Every error is one line naming
// the file, the line and the field: "study.toml:12: tasks[2].trials: must be >= 1".
// Everything is checked: tasks and task settings, factor references, the design's constraints,
// and every stimulus the design can ask for with the renderer's own checks (built-in scene names
// and parameters, glTF files that exist and load, styles and their settings), so `tlab design`
// fails on whatever `simulate` or `run` would fail on later.
#include <stdexcept>
#include <string>

#include "study/design/experiment.hpp"

namespace tlab::study {

class ExperimentFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads `path`. Throws ExperimentFileError.
Experiment readExperimentFile(const std::string& path);
// Whether the stimuli are checked: Skip for the text stored in a study database (an archived
// study is analysed where its glTF files may no longer be).
enum class StimulusChecks { Run, Skip };

// Parses experiment text; `path` names it in messages.
Experiment parseExperiment(const std::string& text, const std::string& path, StimulusChecks checks = StimulusChecks::Run);

}  // namespace tlab::study
