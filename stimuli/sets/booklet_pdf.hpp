#pragma once
// A printable booklet for paper-based studies (as in Carnecky et al.'s user study): one stimulus
// per A4 page with its number, the picture, the question, and answer boxes — one box per probe
// label for choices, or a single box. Cairo PDF surface; the creation date is fixed so the same set
// gives the same bytes.
#include <string>
#include <vector>

#include "stimuli/sets/stimulus_set_renderer.hpp"

namespace tlab::stimuli {

// `folder`: where the stimuli's images are (the set's output folder).
void writeBookletPdf(const std::string& path, const StimulusSetSpec& spec, const std::vector<RenderedStimulus>& stimuli,
                     const std::string& folder);

}  // namespace tlab::stimuli
