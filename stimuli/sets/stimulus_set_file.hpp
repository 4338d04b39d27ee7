#pragma once
// The stimulus-set file (TOML), until the study issue's experiment file takes over:
//
//   [set]
//   name = "carnecky-mini"
//   size = "1024x1024"
//   seed = 7
//   styles = ["opaque", "constant", { name = "constant", set = ["alpha=0.4"] }]
//   booklet = true
//
//   [[scene]]
//   source = "builtin:pretzel"
//   views = [{ azimuth = 0, elevation = 0 }, { azimuth = 60, elevation = 20 }]
//   [[scene.probes]]
//   task = "layer-index"
//   count = 2
//   seed = 3
//   settings = ["min-layers=3"]
//
// Unknown keys are errors (typos must not pass silently); every error names file:line:field.
#include <string>

#include "stimuli/sets/stimulus_set_spec.hpp"

namespace tlab::stimuli {

// Throws StimulusSetError.
StimulusSetSpec readStimulusSetFile(const std::string& path);
StimulusSetSpec parseStimulusSet(const std::string& text, const std::string& fileName);

class StimulusSetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tlab::stimuli
