// Fuzz target: stimulus-set file text (TOML, `tlab stimuli FILE`) through toml++ and our checks of
// every field — styles and their settings, scenes and their views, probes and their tasks. Every
// rejection must be a StimulusSetError naming the file (file:line:field), nothing else.
// fuzz-sources: stimuli/sets/stimulus_set_file.cpp
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "stimuli/sets/stimulus_set_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    tlab::stimuli::parseStimulusSet(text, "fuzz.toml");
  } catch (const tlab::stimuli::StimulusSetError& e) {
    if (std::string(e.what()).rfind("fuzz.toml", 0) != 0) std::abort();
  }
  return 0;
}
