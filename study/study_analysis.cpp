#include "study/study_analysis.hpp"

#include <map>

#include "analysis/analysis_error.hpp"
#include "analysis/number_format.hpp"

namespace tlab::study {

namespace {

// Per subject, the mean of the dependent variable at each level of `factor` (subjects with
// every level only).
std::map<std::string, std::map<std::string, double>> subjectLevelMeans(const analysis::Table& table, const std::string& factor,
                                                                       const std::string& dv) {
  const std::size_t subject = table.columnIndex("participant"), f = table.columnIndex(factor), y = table.columnIndex(dv);
  std::map<std::string, std::map<std::string, std::pair<double, int>>> sums;
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    auto& cell = sums[table.text(r, subject)][table.text(r, f)];
    cell.first += table.number(r, y);
    cell.second += 1;
  }
  std::map<std::string, std::map<std::string, double>> means;
  for (const auto& [s, levels] : sums)
    for (const auto& [l, sum] : levels) means[s][l] = sum.first / sum.second;
  return means;
}

void addPairwise(StudyAnalysis& out, const analysis::Table& table, const Experiment& e, const std::string& dv) {
  for (const auto& name : out.spec.within) {
    const Factor* factor = e.factor(name);
    if (!factor || factor->levels.size() <= 2) continue;
    const auto means = subjectLevelMeans(table, name, dv);
    for (std::size_t a = 0; a < factor->levels.size(); ++a)
      for (std::size_t b = a + 1; b < factor->levels.size(); ++b) {
        std::vector<double> x, y;
        for (const auto& [s, levels] : means) {
          const auto la = levels.find(factor->levels[a].name), lb = levels.find(factor->levels[b].name);
          if (la == levels.end() || lb == levels.end()) continue;
          x.push_back(la->second);
          y.push_back(lb->second);
        }
        try {
          out.pairwise.push_back({dv, name, factor->levels[a].name, factor->levels[b].name,
                                  analysis::pairedTTest(x, y, analysis::Alternative::TwoSided, 1.0 - out.spec.alpha)});
        } catch (const analysis::AnalysisError& error) {
          out.errors.push_back(dv + ": " + name + " " + factor->levels[a].name + " vs " + factor->levels[b].name + ": " + error.what());
        }
      }
  }
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
  for (const auto& pw : pairwise) out.push_back({pw.dv + ": " + pw.factor + " " + pw.first + " vs " + pw.second + " paired t", pw.test.p});
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
        const analysis::Table table = analysisTable(store, stored, spec, dv);
        const analysis::Report r = analysis::makeReport(table, analysisPlan(spec, dv));
        if (a.report.dependentVariables.empty()) {
          a.report.plan = r.plan;
          a.report.design = r.design;
        } else {
          a.report.plan.dependentVariables.push_back(dv);
        }
        a.report.dependentVariables.insert(a.report.dependentVariables.end(), r.dependentVariables.begin(), r.dependentVariables.end());
        a.report.notes.insert(a.report.notes.end(), r.notes.begin(), r.notes.end());
        if (std::find(spec.tests.begin(), spec.tests.end(), "t-tests") != spec.tests.end()) addPairwise(a, table, stored.experiment, dv);
      } catch (const analysis::AnalysisError& error) {
        a.errors.push_back(dv + ": " + error.what());
      }
    }
    for (const auto& pw : a.pairwise)
      a.report.notes.push_back("Pairwise paired t-test, " + pw.dv + ", " + pw.factor + " " + pw.first + " vs " + pw.second + ": t(" +
                               analysis::formatNumber(pw.test.df) + ") = " + analysis::formatNumber(pw.test.t) + ", p = " +
                               analysis::formatP(pw.test.p) + ", mean difference " + analysis::formatNumber(pw.test.meanDiff));
    for (const auto& e : a.errors) a.report.notes.push_back(e);
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace tlab::study
