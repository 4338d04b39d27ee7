#pragma once
// Images from another renderer an experiment shows (Level::images): every file a design can show,
// found by expanding the levels' path templates over one balanced round of participant slots, and
// the SHA-256 of each file's bytes — the raw image's identity, recorded in the experiment's stored
// text ("# tlab image file WRITTEN = PATH sha256 HEX", WRITTEN relative to the experiment file) and
// part of the design's fingerprint, so a re-rendered image makes a new experiment version that is
// not pooled with the old one unless asked.
#include <string>
#include <vector>

#include "study/design/experiment.hpp"
#include "study/design/session_plan.hpp"

namespace tlab::study {

// The stimuli that show an image, once per image, in the order the design first shows them.
std::vector<StimulusKey> externalImageStimuli(const Experiment& e);

// A task with navigation draws tlab's live view of the scene, which cannot show a picture from
// another renderer: refused (ExperimentFileError naming the task's navigation field) when one of
// its trials would show images.
void refuseLiveViewsOfImages(const Experiment& e);

// The raw images' identities a text records (StyleFileUse: written, path, sha256).
std::vector<StyleFileUse> recordedImageFiles(const std::string& text);

// Appends the identities of the images the design shows to e.text, unless it records them already
// (a text read back from a database) or `readFiles` is false. An image that cannot be read is left
// out here: the alignment check names it.
void recordImageFiles(Experiment& e, bool readFiles);

}  // namespace tlab::study
