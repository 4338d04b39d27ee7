#pragma once
// Before `tlab serve` listens: the checks that only an online run makes (walking needs the live
// window) and every stimulus, floor plan and turntable view of the slots the study will use,
// rendered once, so that no participant waits for a rendering.
#include "study/design/experiment.hpp"
#include "study/serve/render_worker.hpp"

namespace tlab::study {

// Throws ExperimentFileError "file:line: tasks[i].navigation: ..." for a walking task.
void checkOnlineExperiment(const Experiment& experiment);

struct PreparedStudy {
  int slots = 0, trials = 0, images = 0;
};

// Every planned trial of the first `slots` slots (one balanced cycle of the design covers every
// stimulus; later slots reorder them), with a progress bar on a terminal.
PreparedStudy prepareStudy(const Experiment& experiment, RenderWorker& worker, int slots, bool progressBar);

}  // namespace tlab::study
