#include "study/serve/study_preparation.hpp"

#include <set>

#include "stimuli/sets/progress_bar.hpp"
#include "study/design/counterbalancing.hpp"
#include "study/design/experiment_file.hpp"

namespace tlab::study {

void checkOnlineExperiment(const Experiment& experiment) {
  for (const auto& t : experiment.tasks)
    if (t.navigation == Navigation::Walk && !experiment.online.live)
      throw ExperimentFileError(t.navigationSource + ": walking through a scene needs live views: [online] live = false shows only "
                                                     "orbit tasks online, as pre-rendered turntables");
}

PreparedStudy prepareStudy(const Experiment& experiment, RenderWorker& worker, int slots, bool progressBar) {
  const Design design = makeDesign(experiment);
  std::vector<PlannedTrial> all;
  for (int slot = 0; slot < slots; ++slot) {
    const SessionPlan plan = makeSessionPlan(experiment, design, slot);
    all.insert(all.end(), plan.trials.begin(), plan.trials.end());
  }
  PreparedStudy out;
  out.slots = slots;
  std::set<std::string> images;
  stimuli::ProgressBar bar("stimuli", all.size(), progressBar);
  for (const auto& trial : all) {
    const PreparedTrial prepared = worker.prepare(trial);
    const TrialImages extra = worker.images(trial, prepared);
    images.insert(prepared.stimulusSha256);
    if (!extra.floorPlanSha256.empty()) images.insert(extra.floorPlanSha256);
    if (extra.turntable)
      for (const auto& v : extra.turntable->views) images.insert(v.sha256);
    ++out.trials;
    bar.advance();
  }
  out.images = int(images.size());
  return out;
}

}  // namespace tlab::study
