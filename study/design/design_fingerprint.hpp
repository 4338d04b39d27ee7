#pragma once
// The design of an experiment as one hash: what decides which stimuli, questions and orders a
// participant gets and how the data are laid out — seed, stimulus, factors and levels (scene,
// style, camera, settings), counterbalancing, block tasks, tasks with their settings and limits,
// questionnaire items and points. Titles, welcome and goodbye texts, instructions, item wording,
// the participant count, the analysis plan and the simulated observer are not part of it: two
// versions of an experiment that differ only there pool without asking.
#include <string>

#include "study/design/experiment.hpp"

namespace tlab::study {

// SHA-256 (hex) of a canonical JSON text of the design.
std::string designFingerprint(const Experiment& experiment);

}  // namespace tlab::study
