#include "study/design/session_plan.hpp"

#include <filesystem>
#include <set>

#include "study/design/order_permutations.hpp"

namespace tlab::study {

const char* phaseName(Phase phase) { return phase == Phase::Training ? "training" : "test"; }

std::string StimulusKey::text() const {
  std::string t = scene + " | " + style + " |";
  for (const auto& s : renderSettings) t += " " + s;
  t += " | " + camera + " | " + std::to_string(width) + "x" + std::to_string(height);
  return images.empty() ? t : t + " | images " + images;
}

std::string StimulusKey::viewText() const { return scene + " | " + camera + " | " + std::to_string(width) + "x" + std::to_string(height); }

namespace {

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t p = text.find(from); p != std::string::npos; p = text.find(from, p + to.size())) text.replace(p, from.size(), to);
  return text;
}

StimulusKey stimulusFor(const Experiment& e, const TaskSpec& task, const Condition& condition, int sceneInstance) {
  StimulusKey key{e.stimulus.scene, e.stimulus.style, e.stimulus.camera, e.stimulus.renderSettings, e.stimulus.width, e.stimulus.height};
  for (std::size_t i = 0; i < e.factors.size(); ++i) {
    const Level& level = e.factors[i].levels[std::size_t(condition.levels[i])];
    if (level.scene) key.scene = *level.scene;
    if (level.style) key.style = *level.style;
    if (level.camera) key.camera = *level.camera;
    if (level.images) key.images = *level.images;
    key.renderSettings.insert(key.renderSettings.end(), level.renderSettings.begin(), level.renderSettings.end());
  }
  if (task.scene) key.scene = *task.scene;
  key.scene = replaceAll(key.scene, "{trial}", std::to_string(sceneInstance));
  if (!key.images.empty()) {  // relative to the experiment file; {FACTOR}: that factor's level in this condition
    namespace fs = std::filesystem;
    key.images = fs::absolute(fs::path(e.path).parent_path() / key.images).lexically_normal().string();
    key.images = replaceAll(key.images, "{trial}", std::to_string(sceneInstance));
    for (std::size_t i = 0; i < e.factors.size(); ++i)
      key.images = replaceAll(key.images, "{" + e.factors[i].name + "}", e.factors[i].levels[std::size_t(condition.levels[i])].name);
  }
  return key;
}

bool taskApplies(const TaskSpec& task, const std::map<std::string, std::string>& levels) {
  for (const auto& [factor, level] : task.when)
    if (levels.at(factor) != level) return false;
  return true;
}

// Appends the questions of `trials` trials of one task in one condition.
void appendTrials(const Experiment& e, const Design& design, const TaskSpec& task, const Condition& condition, int block,
                  Phase phase, int trials, std::vector<PlannedTrial>& out) {
  for (int t = 1; t <= trials; ++t) {
    // Training scenes use instances after the test ones, so training never shows a test stimulus.
    const int instance = phase == Phase::Test ? t : task.trials + t;
    const StimulusKey stimulus = stimulusFor(e, task, condition, instance);
    std::uint64_t seed = mixSeed(e.seed, task.id);
    seed = mixSeed(seed, stimulus.scene);
    seed = mixSeed(seed, std::uint64_t(instance));
    for (int q = 1; q <= task.questions; ++q) {
      PlannedTrial p;
      p.sequence = int(out.size()) + 1;
      p.phase = phase;
      p.block = block;
      p.condition = design.describe(condition);
      p.levels = design.levelNames(condition);
      p.taskId = task.id;
      p.task = task.task;
      p.taskSettings = task.settings;
      p.trial = t;
      p.question = q;
      p.questionsInTrial = task.questions;
      p.stimulus = stimulus;
      p.probeSeed = seed;
      p.timeLimitSeconds = task.timeLimitSeconds;
      p.trialTimeLimitSeconds = task.trialTimeLimitSeconds;
      p.navigation = task.navigation;
      out.push_back(std::move(p));
    }
  }
}

}  // namespace

SessionPlan makeSessionPlan(const Experiment& e, const Design& design, int slot) {
  SessionPlan plan;
  plan.design = design.slot(slot);
  std::set<std::string> trained;
  for (std::size_t b = 0; b < plan.design.blocks.size(); ++b) {
    const Condition& condition = plan.design.blocks[b];
    const auto levels = design.levelNames(condition);
    std::vector<const TaskSpec*> blockTasks;
    if (e.blockTasks == BlockTasks::ByPosition) blockTasks.push_back(&e.tasks[b]);
    else
      for (const auto& t : e.tasks)
        if (taskApplies(t, levels)) blockTasks.push_back(&t);
    for (const TaskSpec* task : blockTasks) {
      if (task->trainingTrials > 0 && trained.insert(task->id).second)
        appendTrials(e, design, *task, condition, int(b) + 1, Phase::Training, task->trainingTrials, plan.trials);
      appendTrials(e, design, *task, condition, int(b) + 1, Phase::Test, task->trials, plan.trials);
    }
  }
  return plan;
}

}  // namespace tlab::study
