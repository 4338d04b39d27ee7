#include "study/design/design_fingerprint.hpp"

#include <nlohmann/json.hpp>

#include "core/sha256.hpp"
#include "study/design/image_files.hpp"
#include "study/design/style_files.hpp"

namespace tlab::study {

namespace {

nlohmann::json levelJson(const Experiment& e, const Level& l) {
  nlohmann::json j = {{"name", l.name}, {"scene", l.scene.value_or("")}, {"style", styleIdentity(e, l.style.value_or(""))},
                      {"camera", l.camera.value_or("")}, {"settings", l.renderSettings}};
  if (l.images) j["images"] = *l.images;  // only when set: designs without images keep their fingerprints
  return j;
}

nlohmann::json taskJson(const TaskSpec& t) {
  return {{"id", t.id},
          {"task", t.task},
          {"trials", t.trials},
          {"questions", t.questions},
          {"training", t.trainingTrials},
          {"limit", t.timeLimitSeconds},
          {"trial_limit", t.trialTimeLimitSeconds.value_or(-1.0)},
          {"settings", t.settings},
          {"when", t.when},
          {"scene", t.scene.value_or("")},
          {"navigation", navigationName(t.navigation)}};
}

}  // namespace

std::string designFingerprint(const Experiment& e) {
  nlohmann::json d;
  d["seed"] = e.seed;
  d["stimulus"] = {{"scene", e.stimulus.scene}, {"style", styleIdentity(e, e.stimulus.style)}, {"camera", e.stimulus.camera},
                   {"settings", e.stimulus.renderSettings}, {"size", {e.stimulus.width, e.stimulus.height}}};
  for (const auto& f : e.factors) {
    nlohmann::json levels = nlohmann::json::array();
    for (const auto& l : f.levels) levels.push_back(levelJson(e, l));
    d["factors"].push_back({{"name", f.name}, {"kind", f.kind == FactorKind::Within ? "within" : "between"}, {"levels", levels}});
  }
  d["counterbalancing"] = counterbalancingName(e.counterbalancing);
  d["block_tasks"] = e.blockTasks == BlockTasks::All ? "all" : "by-position";
  for (const auto& t : e.tasks) d["tasks"].push_back(taskJson(t));
  for (const auto& q : e.questionnaires) {
    nlohmann::json items = nlohmann::json::array();
    for (const auto& i : q.items) items.push_back({i.id, fieldKindName(i.kind), i.points, i.options, i.minimum, i.maximum});
    d["questionnaires"].push_back({{"id", q.id}, {"when", q.when}, {"items", items}});
  }
  for (const auto& f : e.info) d["info"].push_back({f.id, fieldKindName(f.kind), f.options, f.minimum, f.maximum});
  d["consent"] = e.consent.has_value();
  d["breaks"] = {e.breaks.every, e.breaks.blocks, e.breaks.minSeconds};
  d["training_feedback"] = e.trainingFeedback;
  for (const auto& image : recordedImageFiles(e.text)) d["images"].push_back({image.written, image.sha256});  // absent without images
  return core::sha256Hex(d.dump());
}

}  // namespace tlab::study
