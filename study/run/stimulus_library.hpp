#pragma once
// StimulusLibrary: turns a planned trial into what the participant sees and what is scored — the
// rendered picture of its scene/style/camera (rendered once per stimulus key), the task's
// questions for its probe seed (probed once per trial), and the marked stimulus (picture + the
// probe marks and labels) written content-addressed as DIR/<sha256>.png. The study-side face of
// stimuli::StimulusProducer, which makes the picture and the marked stimulus. Needs a current GL
// context (headless or the runner's window).
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/camera.hpp"
#include "study/run/canvas.hpp"
#include "study/run/floor_plan.hpp"
#include "study/run/question_marks.hpp"
#include "study/design/session_plan.hpp"
#include "study/run/stimulus_source.hpp"
#include "study/run/text_painter.hpp"
#include "tasks/question.hpp"

namespace tlab::study {

struct PreparedTrial {
  tasks::Question question;
  std::shared_ptr<const core::Image> picture;  // the rendering without marks (the observer looks here)
  std::shared_ptr<const render::Scene> scene;    // its scene and camera (interactive trials render live from here)
  render::Camera camera;
  std::shared_ptr<const Canvas> stimulus;        // as shown: picture + marks
  std::string stimulusPath;
  std::string stimulusSha256;
  // Floor-point answers (Elmqvist T3): the top-down plan the participant clicks, and its mapping.
  std::optional<FloorPlan> floorPlan;
  std::shared_ptr<const Canvas> floorPlanImage;
};

// The probe points a participant is shown (targets of search tasks are not marked).
bool isMarkedPoint(const tasks::ProbePoint& point);

// The PNG of a stimulus from another renderer (key.images), checked to have the stimulus' size.
core::Image readExternalImage(const StimulusKey& key);
// The scene of a stimulus, loaded from its key (a built-in of `catalog` or a file) and checked to
// have triangles: what a live view renders (the library's pictures and `tlab replay` load it alike).
std::shared_ptr<render::Scene> loadStimulusScene(const StimulusKey& key, const std::vector<render::BuiltinSceneSpec>& catalog);
// The camera a stimulus is drawn with: the key's camera on the scene's own (or the fitted one).
render::Camera stimulusCamera(const render::Scene& scene, const StimulusKey& key);

// Draws the marks of a question's points (ring + label) onto a copy of the picture.
Canvas markQuestion(const core::Image& picture, const tasks::Question& question, TextPainter& painter);

class StimulusLibrary : public StimulusSource {
 public:
  StimulusLibrary(std::string directory, std::vector<render::BuiltinSceneSpec> catalog, TextPainter& painter);

  // Throws with a one-line message naming the scene, style or task when one of them fails.
  PreparedTrial prepare(const PlannedTrial& trial) override;

 private:
  struct Rendered {
    std::shared_ptr<const core::Image> picture;
    std::shared_ptr<render::Scene> scene;
    render::Camera camera;
  };
  const Rendered& rendered(const StimulusKey& key);
  const std::vector<tasks::Question>& questions(const PlannedTrial& trial);
  const std::pair<FloorPlan, std::shared_ptr<const Canvas>>& floorPlan(const StimulusKey& key);

  std::string directory_;
  std::vector<render::BuiltinSceneSpec> catalog_;
  OutlinedMarkPainter marks_;  // the study's look of the marks (StimulusProducer draws with it)
  std::map<std::string, Rendered> pictures_;
  std::map<std::string, std::vector<tasks::Question>> questions_;
  std::map<std::string, std::pair<std::string, std::shared_ptr<const Canvas>>> written_;
  std::map<std::string, std::pair<FloorPlan, std::shared_ptr<const Canvas>>> plans_;  // key → (sha, canvas)
  int prepared_ = 0;  // prepare() calls of this library (fault points)
};

// Where a study database keeps its stimuli: "study.db" → "study-stimuli/".
std::string stimulusDirectoryFor(const std::string& databasePath);

// The task settings a planned trial probes with: its own plus time-limit from the experiment.
std::vector<std::string> effectiveTaskSettings(const PlannedTrial& trial);

// Everything a prepared trial depends on — the stimulus, the task with its settings, the probe
// seed and the question — as one text: the key of every cache of prepared trials.
std::string preparedTrialKey(const PlannedTrial& trial);

}  // namespace tlab::study
