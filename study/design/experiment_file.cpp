// parseExperiment: the experiment file's top-level keys, [stimulus], [[factors]], [[tasks]],
// [[analysis]] and [observer], and the design check. The session flow's sections:
// session_flow_file.cpp; the renderer's checks of every stimulus: stimulus_checks.cpp.
#include "study/design/experiment_file.hpp"
#include "core/file_text.hpp"
#include "core/toml_syntax_message.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "analysis/analysis_error.hpp"
#include "analysis/model_formula.hpp"
#include "analysis/p_adjust.hpp"
#include "study/design/counterbalancing.hpp"
#include "study/design/field_reader.hpp"
#include "study/design/session_flow_file.hpp"
#include "study/design/stimulus_checks.hpp"
#include "study/design/image_files.hpp"
#include "study/design/style_files.hpp"
#include "tasks/task_registry.hpp"

namespace tlab::study {

namespace {

std::pair<int, int> parseSizeField(const FieldReader& r, const toml::table& t, const std::string& where, std::pair<int, int> fallback) {
  const toml::node* n = t.get("size");
  if (!n) return fallback;
  int w = 0, h = 0;
  char x = 0, extra = 0;
  const std::string text = n->is_string() ? n->as_string()->get() : "";
  std::istringstream s(text);
  if (!(s >> w >> x >> h) || x != 'x' || (s >> extra) || w < 16 || h < 16 || w > 8192 || h > 8192)
    r.fail(n, FieldReader::name(where, "size"), "expected \"WxH\" between 16x16 and 8192x8192");
  return {w, h};
}

Level readLevel(const FieldReader& r, const toml::node& node, const std::string& where) {
  Level level;
  if (node.is_string()) {
    level.name = node.as_string()->get();
  } else if (const toml::table* t = node.as_table()) {
    r.checkKeys(*t, where, {"name", "scene", "style", "camera", "settings", "images"});
    level.name = r.string(*t, "name", where, true);
    if (t->get("scene")) level.scene = r.string(*t, "scene", where, true);
    if (t->get("style")) level.style = r.string(*t, "style", where, true);
    if (t->get("camera")) level.camera = r.string(*t, "camera", where, true);
    level.renderSettings = r.strings(*t, "settings", where);
    if (t->get("images")) {
      level.images = r.string(*t, "images", where, true);
      if (level.style) r.fail(t->get("style"), where + ".style", "a level shows either tlab's pictures in a style or images, not both");
      if (level.images->size() < 5 || level.images->substr(level.images->size() - 4) != ".png")
        r.fail(t->get("images"), where + ".images", "expected a PNG path template such as \"renders/{scene}.png\"");
    }
  } else {
    r.fail(&node, where, "a level is a name or a table { name = ..., scene/style/camera/settings = ... }");
  }
  if (level.name.empty()) r.fail(&node, where, "empty level name");
  return level;
}

const std::set<std::string> kReservedNames = {"participant", "task", "task_id", "trial", "block", "question", "phase",
                                              "correct", "score", "rt", "error", "partial_credit", "answered", "slot"};

std::vector<Factor> readFactors(const FieldReader& r, const toml::table& root) {
  std::vector<Factor> factors;
  const auto tables = r.tables(root, "factors");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const toml::table& t = *tables[i];
    const std::string where = "factors[" + std::to_string(i + 1) + "]";
    r.checkKeys(t, where, {"name", "kind", "levels"});
    Factor f;
    f.name = r.string(t, "name", where, true);
    if (f.name.empty() || kReservedNames.count(f.name)) r.fail(t.get("name"), where + ".name", "'" + f.name + "' is empty or reserved");
    for (const auto& g : factors)
      if (g.name == f.name) r.fail(t.get("name"), where + ".name", "factor '" + f.name + "' is defined twice");
    const std::string kind = r.string(t, "kind", where, false, "within");
    if (kind == "within") f.kind = FactorKind::Within;
    else if (kind == "between") f.kind = FactorKind::Between;
    else r.fail(t.get("kind"), where + ".kind", "expected \"within\" or \"between\", got '" + kind + "'");
    const toml::array* levels = t.get("levels") ? t.get("levels")->as_array() : nullptr;
    if (!levels) r.fail(t.get("levels") ? t.get("levels") : &t, where + ".levels", "an array of at least two levels is required");
    for (std::size_t k = 0; k < levels->size(); ++k) {
      Level level = readLevel(r, *levels->get(k), where + ".levels[" + std::to_string(k + 1) + "]");
      if (f.levelIndex(level.name) >= 0)
        r.fail(levels->get(k), where + ".levels", "level '" + level.name + "' is listed twice");
      f.levels.push_back(std::move(level));
    }
    if (f.levels.size() < 2) r.fail(levels, where + ".levels", "a factor needs at least two levels");
    factors.push_back(std::move(f));
  }
  return factors;
}

Counterbalancing parseCounterbalancing(const FieldReader& r, const toml::table& root) {
  const std::string text = r.string(root, "counterbalancing", "", false, "latin-square");
  for (const auto c : {Counterbalancing::Fixed, Counterbalancing::LatinSquare, Counterbalancing::Williams,
                       Counterbalancing::GraecoLatin, Counterbalancing::Permutation, Counterbalancing::Random})
    if (text == counterbalancingName(c)) return c;
  r.fail(root.get("counterbalancing"), "counterbalancing",
         "expected fixed, latin-square, williams, graeco-latin, permutation or random, got '" + text + "'");
}

std::vector<TaskSpec> readTasks(const FieldReader& r, const toml::table& root, const std::vector<Factor>& factors) {
  std::vector<TaskSpec> specs;
  const auto tables = r.tables(root, "tasks");
  if (tables.empty()) r.fail(&root, "tasks", "at least one [[tasks]] table is required");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const toml::table& t = *tables[i];
    const std::string where = "tasks[" + std::to_string(i + 1) + "]";
    r.checkKeys(t, where, {"id", "task", "trials", "questions", "training_trials", "time_limit", "trial_time_limit", "settings",
                           "when", "instructions", "scene", "navigation"});
    TaskSpec s;
    s.task = r.string(t, "task", where, true);
    s.id = r.string(t, "id", where, false, s.task);
    for (const auto& o : specs)
      if (o.id == s.id) r.fail(&t, where + ".id", "task id '" + s.id + "' is used twice");
    try {
      const auto task = tasks::makeTask(s.task);
      s.settings = r.strings(t, "settings", where);
      task->settings(s.settings);
    } catch (const std::invalid_argument& e) {
      r.fail(t.get("settings") ? t.get("settings") : t.get("task"), where, e.what());
    }
    s.trials = int(r.integer(t, "trials", where, 1, 1));
    s.questions = int(r.integer(t, "questions", where, 1, 1));
    s.trainingTrials = int(r.integer(t, "training_trials", where, 0, 0));
    s.settingsSource = t.get("settings") ? r.at(t.get("settings"), where + ".settings") : r.at(&t, where);
    s.trainingSource = r.at(t.get("training_trials") ? t.get("training_trials") : &t, where + ".training_trials");
    s.timeLimitSeconds = r.number(t, "time_limit", where, 120.0, 0.5, 86400.0);
    if (t.get("trial_time_limit")) s.trialTimeLimitSeconds = r.number(t, "trial_time_limit", where, 120.0, 0.5, 86400.0);
    s.instructions = r.string(t, "instructions", where, false);
    if (t.get("scene")) s.scene = r.string(t, "scene", where, true);
    if (t.get("navigation")) {
      try {
        s.navigation = parseNavigation(r.string(t, "navigation", where, true));
        s.navigationSource = r.at(t.get("navigation"), where + ".navigation");
      } catch (const std::invalid_argument& e) {
        r.fail(t.get("navigation"), where + ".navigation", e.what());
      }
      // Marks and labels are drawn on the still picture: only search tasks can move the camera.
      if (s.navigation != Navigation::None && s.task != "counting" && s.task != "pattern" && s.task != "target-discovery")
        r.fail(t.get("navigation"), where + ".navigation",
               "only counting, pattern and target-discovery trials can be explored live (task '" + s.task + "' marks points on the picture)");
    }
    if (const toml::table* when = r.table(t, "when", where)) {
      for (auto&& [key, value] : *when) {
        const std::string factorName(key.str());
        const auto f = std::find_if(factors.begin(), factors.end(), [&](const Factor& x) { return x.name == factorName; });
        if (f == factors.end()) r.fail(&value, where + ".when." + factorName, "no factor of that name");
        if (!value.is_string() || f->levelIndex(value.as_string()->get()) < 0)
          r.fail(&value, where + ".when." + factorName, "must name a level of factor '" + factorName + "'");
        s.when[factorName] = value.as_string()->get();
      }
    }
    specs.push_back(std::move(s));
  }
  return specs;
}

const std::set<std::string> kDependentVariables = {"correct", "score", "rt", "error", "partial_credit", "answered"};

std::vector<AnalysisSpec> readAnalyses(const FieldReader& r, const toml::table& root, const Experiment& e) {
  std::vector<AnalysisSpec> out;
  const auto tables = r.tables(root, "analysis");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const toml::table& t = *tables[i];
    const std::string where = "analysis[" + std::to_string(i + 1) + "]";
    r.checkKeys(t, where, {"title", "tasks", "dv", "within", "between", "tests", "alpha", "formula", "correction"});
    AnalysisSpec a;
    a.title = r.string(t, "title", where, false, e.title.empty() ? e.id : e.title);
    a.tasks = r.strings(t, "tasks", where);
    for (const auto& id : a.tasks)
      if (!e.task(id)) r.fail(t.get("tasks"), where + ".tasks", "no task with id '" + id + "'");
    a.dependentVariables = r.strings(t, "dv", where);
    if (a.dependentVariables.empty()) r.fail(&t, where + ".dv", "at least one dependent variable is required");
    for (const auto& dv : a.dependentVariables)
      if (!kDependentVariables.count(dv))
        r.fail(t.get("dv"), where + ".dv", "'" + dv + "' is not one of correct, score, rt, error, partial_credit, answered");
    a.within = r.strings(t, "within", where);
    a.between = r.strings(t, "between", where);
    for (const auto& list : {a.within, a.between})
      for (const auto& f : list)
        if (!e.factor(f)) r.fail(t.get("within"), where, "no factor named '" + f + "'");
    if (t.get("tests")) a.tests = r.strings(t, "tests", where);
    for (const auto& test : a.tests)
      if (test != "anova" && test != "t-tests" && test != "rank-tests" && test != "mixed")
        r.fail(t.get("tests"), where + ".tests", "'" + test + "' is not one of anova, t-tests, rank-tests, mixed");
    a.alpha = r.number(t, "alpha", where, 0.05, 1e-6, 0.5);
    a.formula = r.string(t, "formula", where, false);
    if (!a.formula.empty()) {
      try {
        const analysis::ModelFormula f = analysis::parseModelFormula(a.formula);
        if (std::find(a.dependentVariables.begin(), a.dependentVariables.end(), f.response) == a.dependentVariables.end())
          r.fail(t.get("formula"), where + ".formula", "the response '" + f.response + "' is not one of the analysis's dv");
      } catch (const analysis::AnalysisError& error) {
        r.fail(t.get("formula"), where + ".formula", error.what());
      }
    }
    a.correction = r.string(t, "correction", where, false, a.correction);
    try {
      analysis::parsePAdjustMethod(a.correction);
    } catch (const analysis::AnalysisError& error) {
      r.fail(t.get("correction"), where + ".correction", error.what());
    }
    out.push_back(std::move(a));
  }
  return out;
}

ObserverParams readObserver(const FieldReader& r, const toml::table& root) {
  ObserverParams p;
  const toml::table* t = r.table(root, "observer", "");
  if (!t) return p;
  r.checkKeys(*t, "observer", {"contrast_reference", "sensitivity", "threshold", "skill_spread", "lapse", "layer_penalty",
                               "base_seconds", "slow_seconds", "rt_sigma", "give_up_share", "gauge_degrees", "gauge_growth"});
  p.contrastReference = r.number(*t, "contrast_reference", "observer", p.contrastReference, 1e-4, 1.0);
  p.sensitivity = r.number(*t, "sensitivity", "observer", p.sensitivity, 0.0, 100.0);
  p.threshold = r.number(*t, "threshold", "observer", p.threshold, 0.0, 1.0);
  p.skillSpread = r.number(*t, "skill_spread", "observer", p.skillSpread, 0.0, 3.0);
  p.lapse = r.number(*t, "lapse", "observer", p.lapse, 0.0, 1.0);
  p.layerPenalty = r.number(*t, "layer_penalty", "observer", p.layerPenalty, 0.0, 1.0);
  p.baseSeconds = r.number(*t, "base_seconds", "observer", p.baseSeconds, 0.01, 3600.0);
  p.slowSeconds = r.number(*t, "slow_seconds", "observer", p.slowSeconds, 0.0, 3600.0);
  p.rtSigma = r.number(*t, "rt_sigma", "observer", p.rtSigma, 0.0, 3.0);
  p.giveUpShare = r.number(*t, "give_up_share", "observer", p.giveUpShare, 0.0, 1.0);
  p.gaugeDegrees = r.number(*t, "gauge_degrees", "observer", p.gaugeDegrees, 0.0, 90.0);
  p.gaugeGrowth = r.number(*t, "gauge_growth", "observer", p.gaugeGrowth, 0.0, 100.0);
  return p;
}

Stimulus readStimulus(const FieldReader& r, const toml::table& root) {
  Stimulus s;
  const toml::table* t = r.table(root, "stimulus", "");
  if (!t) return s;
  r.checkKeys(*t, "stimulus", {"scene", "style", "camera", "settings", "size"});
  s.scene = r.string(*t, "scene", "stimulus", false, s.scene);
  s.style = r.string(*t, "style", "stimulus", false, s.style);
  s.camera = r.string(*t, "camera", "stimulus", false);
  s.renderSettings = r.strings(*t, "settings", "stimulus");
  std::tie(s.width, s.height) = parseSizeField(r, *t, "stimulus", {s.width, s.height});
  return s;
}

void checkDesign(const FieldReader& r, const toml::table& root, const Experiment& e) {
  try {
    const Design design = makeDesign(e);
    if (e.blockTasks == BlockTasks::ByPosition && design.blocksPerRow() != e.tasks.size())
      r.fail(root.get("block_tasks"), "block_tasks",
             "\"by-position\" needs one task per block: " + std::to_string(design.blocksPerRow()) + " blocks but " +
                 std::to_string(e.tasks.size()) + " tasks");
  } catch (const DesignError& error) {
    r.fail(root.get("counterbalancing") ? root.get("counterbalancing") : &root, "counterbalancing", error.what());
  }
}

}  // namespace

Experiment parseExperiment(const std::string& text, const std::string& path, StimulusChecks checks) {
  const FieldReader r(path);
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& error) {
    throw ExperimentFileError(path + ":" + core::tomlSyntaxMessage(text, error.source().begin.line, error.description()));
  }
  r.checkKeys(root, "", {"id", "title", "participant_title", "seed", "participants", "counterbalancing", "block_tasks", "welcome",
                         "goodbye", "consent", "info", "standard_info", "training", "breaks", "debrief", "online", "stimulus", "factors", "tasks",
                         "questionnaires", "analysis", "observer"});
  Experiment e;
  e.path = path;
  e.text = text;
  e.id = r.string(root, "id", "", true);
  if (e.id.empty()) r.fail(root.get("id"), "id", "must not be empty");
  e.title = r.string(root, "title", "", false, e.id);
  e.seed = std::uint64_t(r.integer(root, "seed", "", 1, 0));
  e.participants = int(r.integer(root, "participants", "", 1, 1, true));
  e.welcome = r.string(root, "welcome", "", false);
  readSessionFlow(r, root, e);
  e.stimulus = readStimulus(r, root);
  e.factors = readFactors(r, root);
  e.counterbalancing = parseCounterbalancing(r, root);
  const std::string blockTasks = r.string(root, "block_tasks", "", false, "all");
  if (blockTasks == "all") e.blockTasks = BlockTasks::All;
  else if (blockTasks == "by-position") e.blockTasks = BlockTasks::ByPosition;
  else r.fail(root.get("block_tasks"), "block_tasks", "expected \"all\" or \"by-position\", got '" + blockTasks + "'");
  e.tasks = readTasks(r, root, e.factors);
  e.questionnaires = readQuestionnaires(r, root);
  e.analyses = readAnalyses(r, root, e);
  e.observer = readObserver(r, root);
  resolveStyleFiles(r, root, e, checks == StimulusChecks::Run);
  checkDesign(r, root, e);
  if (checks == StimulusChecks::Run) refuseLiveViewsOfImages(e);
  recordImageFiles(e, checks == StimulusChecks::Run);
  if (checks == StimulusChecks::Run) checkStimuli(r, root, e);
  return e;
}

Experiment readExperimentFile(const std::string& path) {
  const auto text = core::readFileText(path);
  if (!text) throw ExperimentFileError(path + ": cannot open the experiment file");
  return parseExperiment(*text, path);
}

}  // namespace tlab::study
