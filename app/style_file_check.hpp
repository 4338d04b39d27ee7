#pragma once
// The design-time checks that need GL, made on a headless context of their own before any
// session, window or picture starts: each style file compiles (else one line "FILE:LINE:
// message"), and each image from another renderer aligns with tlab's view (else one line naming
// the image, its IoU and the likely cause).
#include <string>
#include <vector>

#include "study/design/experiment.hpp"
#include "study/run/external_image_check.hpp"

namespace tlab::app {

// Compiles every style of `styles` that is a file (built-in names are skipped); no context is
// made when there is none.
void compileStyleFiles(const std::vector<std::string>& styles);
// The style files an experiment names, and its images' alignment (one entry per image).
std::vector<study::ImageAlignment> checkExperimentOnGl(const study::Experiment& experiment);

}  // namespace tlab::app
