#pragma once
// The renderer's checks of an experiment file's stimuli: every stimulus the design can ask for
// (each combination of factor levels, with each task's scene) must pass the scene source, style
// and settings checks, failing with the file:line of the field that set the failing part.
#include <toml++/toml.h>

#include "study/design/experiment.hpp"
#include "study/design/field_reader.hpp"

namespace tlab::study {

// Every stimulus the design can ask for — each combination of levels, with each task's scene —
// passes the renderer's checks, so `tlab design` catches what `simulate` or `run` would fail on.
void checkStimuli(const FieldReader& r, const toml::table& root, const Experiment& e);

}  // namespace tlab::study
