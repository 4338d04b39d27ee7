#include "study/run/stimulus_library.hpp"

#include "study/store/fault_point.hpp"
#include "tasks/answer_form.hpp"

#include <filesystem>
#include <sstream>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"
#include "stimuli/sets/external_image_alignment.hpp"
#include "stimuli/sets/stimulus_producer.hpp"
#include "tasks/task_registry.hpp"

namespace tlab::study {

namespace {

std::string numberText(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

render::Camera resolveCamera(const render::Scene& scene, const StimulusKey& key) {
  const render::BoundingSphere sphere = scene.boundingSphere();
  const render::Camera base = scene.camera ? *scene.camera : render::fitCamera(sphere, float(key.width) / float(key.height));
  if (key.camera.empty()) return base;
  const render::Camera c = render::parseCamera(key.camera, base);
  const bool clipGiven = key.camera.find("near=") != std::string::npos || key.camera.find("far=") != std::string::npos;
  return clipGiven ? c : render::fitClipPlanes(c, sphere);
}

}  // namespace

core::Image readExternalImage(const StimulusKey& key) {
  return stimuli::opaque(stimuli::readExternalImage(key.images, key.width, key.height));
}

render::Camera stimulusCamera(const render::Scene& scene, const StimulusKey& key) { return resolveCamera(scene, key); }

std::shared_ptr<render::Scene> loadStimulusScene(const StimulusKey& key, const std::vector<render::BuiltinSceneSpec>& catalog) {
  auto scene = std::make_shared<render::Scene>(render::loadScene(key.scene, catalog));
  render::requireTriangles(*scene, key.scene);
  return scene;
}

bool isMarkedPoint(const tasks::ProbePoint& p) { return p.role != "target" && p.role != "gauge"; }

Canvas markQuestion(const core::Image& picture, const tasks::Question& question, TextPainter& painter) {
  return drawOutlinedMarks(picture, stimuli::visibleMarks(probeMarks(question)), painter);
}

std::string stimulusDirectoryFor(const std::string& databasePath) {
  // A server URL (postgresql://user@host/NAME?...): NAME-stimuli in the working directory, as for
  // a database file NAME.db there (a server has no folder next to which the pictures could lie).
  const auto scheme = databasePath.find("://");
  if (databasePath.rfind("postgres", 0) == 0 && scheme != std::string::npos) {
    const auto slash = databasePath.find('/', scheme + 3);
    std::string name = slash == std::string::npos ? "" : databasePath.substr(slash + 1, databasePath.find_first_of("?#", slash + 1) - slash - 1);
    for (auto& c : name)
      if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.')) c = '_';
    return (name.empty() ? std::string("postgresql") : name) + "-stimuli";
  }
  const std::filesystem::path db(databasePath);
  return (db.parent_path() / (db.stem().string() + "-stimuli")).string();
}

std::string preparedTrialKey(const PlannedTrial& trial) {
  std::string key = trial.stimulus.text() + " | " + trial.task + " | " + std::to_string(trial.probeSeed) + " | q" +
                    std::to_string(trial.question) + "/" + std::to_string(trial.questionsInTrial);
  for (const auto& s : effectiveTaskSettings(trial)) key += " " + s;
  return key;
}

std::vector<std::string> effectiveTaskSettings(const PlannedTrial& trial) {
  std::vector<std::string> settings = trial.taskSettings;
  bool hasLimit = false;
  for (const auto& s : settings) hasLimit = hasLimit || s.rfind("time-limit=", 0) == 0;
  if (!hasLimit) settings.push_back("time-limit=" + numberText(trial.timeLimitSeconds));
  return settings;
}

StimulusLibrary::StimulusLibrary(std::string directory, std::vector<render::BuiltinSceneSpec> catalog, TextPainter& painter)
    : directory_(std::move(directory)), catalog_(std::move(catalog)), marks_(painter) {}

const StimulusLibrary::Rendered& StimulusLibrary::rendered(const StimulusKey& key) {
  const std::string id = key.text();
  const auto found = pictures_.find(id);
  if (found != pictures_.end()) return found->second;
  auto scene = loadStimulusScene(key, catalog_);
  stimuli::StimulusView view;
  view.width = key.width;
  view.height = key.height;
  render::findStyle(key.style);
  view.style = key.style;
  for (const auto& s : key.renderSettings) render::addSetting(view.settings, s);
  view.camera = resolveCamera(*scene, key);
  if (!key.images.empty()) {  // another renderer's picture of the same scene and camera (checked by checkExternalImages)
    auto picture = std::make_shared<core::Image>(readExternalImage(key));
    return pictures_.emplace(id, Rendered{std::move(picture), std::move(scene), view.camera}).first->second;
  }
  render::Renderer renderer(*scene);
  auto picture = std::make_shared<core::Image>(stimuli::StimulusProducer::picture(renderer, view));
  return pictures_.emplace(id, Rendered{std::move(picture), std::move(scene), view.camera}).first->second;
}

const std::vector<tasks::Question>& StimulusLibrary::questions(const PlannedTrial& trial) {
  const auto settings = effectiveTaskSettings(trial);
  // Questions depend on the geometry and view only: every style of a scene asks the same ones.
  std::string id = trial.stimulus.viewText() + " | " + trial.task + " | " + std::to_string(trial.probeSeed) + " | " +
                   std::to_string(trial.questionsInTrial);
  for (const auto& s : settings) id += " " + s;
  const auto found = questions_.find(id);
  if (found != questions_.end()) return found->second;
  const Rendered& r = rendered(trial.stimulus);
  const auto task = tasks::makeTask(trial.task);
  const tasks::ProbeRequest request{*r.scene, r.camera, trial.stimulus.width, trial.stimulus.height, trial.questionsInTrial,
                                    trial.probeSeed, task->settings(settings)};
  try {
    return questions_.emplace(id, task->probe(request)).first->second;
  } catch (const std::exception& e) {
    throw std::runtime_error("task " + trial.taskId + " on " + trial.stimulus.scene + ": " + e.what());
  }
}

const std::pair<FloorPlan, std::shared_ptr<const Canvas>>& StimulusLibrary::floorPlan(const StimulusKey& key) {
  const std::string id = key.scene + " | " + std::to_string(key.width) + "x" + std::to_string(key.height);
  const auto found = plans_.find(id);
  if (found != plans_.end()) return found->second;
  const Rendered& r = rendered(key);
  FloorPlan plan = makeFloorPlan(*r.scene, key.width, key.height);
  const stimuli::StimulusView view{key.width, key.height, "opaque", {}, plan.camera};
  render::Renderer renderer(*r.scene);
  auto image = std::make_shared<const Canvas>(stimuli::StimulusProducer::picture(renderer, view));
  return plans_.emplace(id, std::make_pair(plan, std::move(image))).first->second;
}

PreparedTrial StimulusLibrary::prepare(const PlannedTrial& trial) {
  PreparedTrial p;
  p.question = questions(trial).at(std::size_t(trial.question - 1));
  const Rendered& r = rendered(trial.stimulus);
  p.picture = r.picture;
  p.scene = r.scene;
  p.camera = r.camera;
  const std::string id = preparedTrialKey(trial);
  auto found = written_.find(id);
  if (found == written_.end()) {
    const stimuli::ProducedStimulus produced = stimuli::StimulusProducer(marks_).produce(*p.picture, probeMarks(p.question));
    // The canvas shown is the produced image again: its 8-bit pixels convert back exactly.
    auto canvas = std::make_shared<const Canvas>(produced.image);
    const std::string path = (std::filesystem::path(directory_) / (produced.sha256 + ".png")).string();
    if (!std::filesystem::exists(path)) {
      std::filesystem::create_directories(directory_);  // made with its first stimulus: a failed start leaves no folder
      core::writeFileAtomically(path, produced.png);
    }
    found = written_.emplace(id, std::make_pair(produced.sha256, std::move(canvas))).first;
  }
  p.stimulusSha256 = found->second.first;
  p.stimulus = found->second.second;
  p.stimulusPath = (std::filesystem::path(directory_) / (p.stimulusSha256 + ".png")).string();
  if (tasks::answerForm(p.question).widget(p.question).kind == tasks::WidgetKind::FloorPlanPoint) {
    const auto& [plan, image] = floorPlan(trial.stimulus);
    p.floorPlan = plan;
    p.floorPlanImage = image;
  }
  faultPoint("prepare", ++prepared_);
  return p;
}

}  // namespace tlab::study
