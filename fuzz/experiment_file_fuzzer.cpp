// Fuzz target: experiment file text (TOML) → Experiment, through toml++ and our validation.
// Every rejection must be an ExperimentFileError (one line naming file:line), nothing else.
// fuzz-sources: study/design/experiment_file.cpp study/design/participant_texts.cpp study/design/session_flow_file.cpp study/design/stimulus_checks.cpp study/design/style_files.cpp
#include <cstddef>
#include <cstdint>
#include <string>

#include "study/design/experiment_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    tlab::study::parseExperiment(text, "fuzz.toml");
  } catch (const tlab::study::ExperimentFileError&) {
  }
  return 0;
}
