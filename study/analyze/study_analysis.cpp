#include "study/analyze/study_analysis.hpp"

#include <algorithm>
#include <map>

#include "analysis/analysis_error.hpp"
#include "analysis/anova_design.hpp"
#include "analysis/number_format.hpp"
#include "analysis/p_adjust.hpp"
#include "analysis/pairwise_tests.hpp"
#include "analysis/r_moments.hpp"
#include "study/analyze/study_mixed_model.hpp"
#include "study/analyze/study_record_tables.hpp"

namespace tlab::study {

namespace {

// Pairwise paired t-tests of column `dv` (analysis/pairwise_tests.hpp), listed as `label` (the
// variable, and its task when split).
void addPairwise(StudyAnalysis& out, const analysis::Table& table, const Experiment& e, const std::string& dv,
                 const std::string& label) {
  for (const auto& name : out.spec.within) {
    const Factor* factor = e.factor(name);
    if (!factor || factor->levels.size() <= 2) continue;
    std::vector<std::string> levels;
    for (const auto& l : factor->levels) levels.push_back(l.name);
    const std::size_t first = out.pairwise.size();
    for (auto& c : analysis::pairwisePairedTTests(table, "participant", name, levels, dv, 1.0 - out.spec.alpha)) {
      if (c.test) out.pairwise.push_back({label, name, c.first, c.second, *c.test});
      else out.errors.push_back(label + ": " + name + " " + c.first + " vs " + c.second + ": " + c.error);
    }
    // The comparisons of one factor form the family the correction adjusts over (p.adjust).
    std::vector<double> p;
    for (std::size_t k = first; k < out.pairwise.size(); ++k) p.push_back(out.pairwise[k].test.p);
    const auto adjusted = analysis::pAdjust(p, analysis::parsePAdjustMethod(out.spec.correction));
    for (std::size_t k = first; k < out.pairwise.size(); ++k) out.pairwise[k].pAdjusted = adjusted[k - first];
  }
}

bool planned(const AnalysisSpec& spec, const char* test) {
  return std::find(spec.tests.begin(), spec.tests.end(), test) != spec.tests.end();
}

// tests = ["mixed"]: a mixed model per task (the model needs no balance), or of the pooled tasks
// the analysis names.
void addMixedModels(StudyAnalysis& a, const analysis::Table& table, const Experiment& e, const std::string& dv) {
  std::vector<std::string> tasks;
  for (const auto& t : table.textColumn("task"))
    if (std::find(tasks.begin(), tasks.end(), t) == tasks.end()) tasks.push_back(t);
  std::vector<std::pair<std::string, analysis::Table>> parts;
  if (tasks.size() <= 1 || !a.spec.tasks.empty()) parts.emplace_back(dv, table);
  else
    for (const auto& task : tasks) parts.emplace_back(dv + " [task " + task + "]", table.rowsWhere("task", task));
  for (const auto& [label, part] : parts) {
    try {
      a.mixed.push_back({label, fitStudyMixedModel(part, e, a.spec, dv)});
    } catch (const analysis::AnalysisError& error) {
      const std::string what = error.what();
      a.errors.push_back(label + ": " + (what.rfind("mixed model", 0) == 0 ? "" : "mixed model: ") + what);
    }
  }
}

struct TaskTable {
  std::string label;  // "correct", or "correct [task layer-index]"
  analysis::Table table;
};

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
  return out;
}

// The tables one dependent variable is analysed in. Different tasks ask different questions, so
// by default each task is analysed alone; when a task's data cannot be analysed alone (e.g. each
// participant meets each method in a different task, as in Carnecky's design), or the analysis
// names its tasks (tasks = [...]), the tasks are pooled and a note says so.
std::vector<TaskTable> tablesByTask(const analysis::Table& table, const AnalysisSpec& spec, const std::string& dv,
                                    std::vector<std::string>& notes) {
  const bool mixedPlanned = std::find(spec.tests.begin(), spec.tests.end(), "mixed") != spec.tests.end();
  std::vector<std::string> tasks;
  for (const auto& t : table.textColumn("task"))
    if (std::find(tasks.begin(), tasks.end(), t) == tasks.end()) tasks.push_back(t);
  if (tasks.size() <= 1) return {{dv, table}};
  if (!spec.tasks.empty()) {
    notes.push_back(dv + ": pooled over the tasks " + joined(tasks) + ", as the analysis's tasks = [...] asks.");
    return {{dv, table}};
  }
  std::vector<TaskTable> split;
  for (const auto& task : tasks) {
    analysis::Table subset = table.rowsWhere("task", task);
    try {
      analysis::makeAnovaDesign(subset, dv, spec.between, spec.within, "participant");
    } catch (const analysis::AnalysisError& error) {
      notes.push_back(dv + ": " + (mixedPlanned ? "the ANOVA, t-tests and rank tests are " : "") + "pooled over the tasks " +
                      joined(tasks) + " because task '" + task + "' cannot be analysed alone by them (" + error.what() +
                      (mixedPlanned ? "); the mixed model analyses each task alone."
                                    : "); name the tasks to analyse with tasks = [...] in [[analysis]], or plan tests = [\"mixed\"]."));
      return {{dv, table}};
    }
    split.push_back({dv + " [task " + task + "]", std::move(subset)});
  }
  notes.push_back(dv + ": analysed per task (" + joined(tasks) +
                  "), since tasks ask different questions; tasks = [...] in [[analysis]] pools the tasks it names.");
  return split;
}

void addNote(analysis::Report& report, const std::string& note) {
  if (std::find(report.notes.begin(), report.notes.end(), note) == report.notes.end()) report.notes.push_back(note);
}

// One dependent variable (per task, see tablesByTask) merged into the analysis's report.
void addDependentVariable(StudyAnalysis& a, Store& store, const StoredExperiment& stored, const std::string& dv) {
  std::vector<std::string> notes;
  const analysis::Table table = analysisTable(store, stored, a.spec, dv);
  if (planned(a.spec, "mixed")) addMixedModels(a, table, stored.experiment, dv);
  for (const TaskTable& part : tablesByTask(table, a.spec, dv, notes)) {
    analysis::Report r = analysis::makeReport(part.table, analysisPlan(a.spec, dv));
    for (auto& d : r.dependentVariables) d.dv = part.label;
    if (a.report.dependentVariables.empty()) {
      a.report.plan = r.plan;
      a.report.plan.dependentVariables.clear();
      a.report.design = r.design;
    }
    a.report.plan.dependentVariables.push_back(part.label);
    a.report.dependentVariables.insert(a.report.dependentVariables.end(), r.dependentVariables.begin(), r.dependentVariables.end());
    for (const auto& note : r.notes) addNote(a.report, note);
    if (planned(a.spec, "t-tests")) addPairwise(a, part.table, stored.experiment, dv, part.label);
  }
  for (const auto& note : notes) addNote(a.report, note);
}

}  // namespace

std::vector<PlannedPValue> StudyAnalysis::pValues() const {
  std::vector<PlannedPValue> out;
  for (const auto& dv : report.dependentVariables) {
    if (dv.anova)
      for (const auto& effect : dv.anova->effects) out.push_back({dv.dv + ": anova " + effect.name, effect.p});
    for (const auto& c : dv.comparisons) {
      if (c.tTest) out.push_back({dv.dv + ": " + c.factor + " paired/welch t-test", c.tTest->p});
      if (c.wilcoxon) out.push_back({dv.dv + ": " + c.factor + " wilcoxon", c.wilcoxon->p});
      if (c.mannWhitney) out.push_back({dv.dv + ": " + c.factor + " mann-whitney", c.mannWhitney->p});
      if (c.friedman) out.push_back({dv.dv + ": " + c.factor + " friedman", c.friedman->p});
    }
  }
  const bool adjusted = spec.correction != "none";
  for (const auto& pw : pairwise)
    out.push_back({pw.dv + ": " + pw.factor + " " + pw.first + " vs " + pw.second + " paired t" + (adjusted ? " (" + spec.correction + ")" : ""),
                   adjusted ? pw.pAdjusted : pw.test.p});
  for (const auto& m : mixed)
    for (const auto& e : m.result.fixedEffects)
      if (e.term != "(Intercept)") out.push_back({m.dv + ": mixed model " + e.term, e.p});
  return out;
}

std::vector<StudyAnalysis> analyzeStudy(Store& store, const StoredExperiment& stored) {
  std::vector<StudyAnalysis> out;
  for (const auto& spec : stored.experiment.analyses) {
    StudyAnalysis a;
    a.spec = spec;
    a.report.title = spec.title;
    a.report.source = store.location();
    for (const auto& dv : spec.dependentVariables) {
      try {
        addDependentVariable(a, store, stored, dv);
      } catch (const analysis::AnalysisError& error) {
        a.errors.push_back(dv + ": " + error.what());
      }
    }
    if (const std::string w = simulatedDataWarning(participantModes(store, stored), stored.experiment.observer); !w.empty())
      a.report.warnings.push_back(w);
    for (const auto& pw : a.pairwise)
      a.report.notes.push_back("Pairwise paired t-test, " + pw.dv + ", " + pw.factor + " " + pw.first + " vs " + pw.second + ": t(" +
                               analysis::formatNumber(pw.test.df) + ") = " + analysis::formatNumber(pw.test.t) + ", p = " +
                               analysis::formatP(pw.test.p) +
                               (spec.correction != "none" ? " (" + spec.correction + "-adjusted p = " + analysis::formatP(pw.pAdjusted) + ")" : "") +
                               ", mean difference " + analysis::formatNumber(pw.test.meanDiff));
    for (const auto& m : a.mixed) a.report.sections.push_back(mixedModelSection(m.dv, m.result));
    for (const auto& e : a.errors) a.report.notes.push_back(e);
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace tlab::study
