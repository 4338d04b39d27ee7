#include "app/analysis_text.hpp"

#include "analysis/mixed_model_report.hpp"
#include "analysis/number_format.hpp"
#include "analysis/text_table.hpp"

namespace tlab::app {

std::string analysisText(const study::StudyAnalysis& a) {
  std::string out = "== " + a.spec.title + " (" + std::to_string(a.report.design.subjects) + " subjects, " + std::to_string(a.report.design.rows) + " rows)\n";
  for (const auto& warning : a.report.warnings) out += warning + "\n";
  analysis::TextTable table;
  table.header = {"dv", "test", "statistic", "p"};
  for (const auto& dv : a.report.dependentVariables) {
    if (dv.anova)
      for (const auto& e : dv.anova->effects)
        table.rows.push_back({dv.dv, "ANOVA " + e.name,
                              "F(" + analysis::formatNumber(e.df1) + ", " + analysis::formatNumber(e.df2) + ") = " + analysis::formatNumber(e.F),
                              analysis::formatP(e.p)});
    if (!dv.anovaError.empty()) table.rows.push_back({dv.dv, "ANOVA", dv.anovaError, ""});
    for (const auto& c : dv.comparisons) {
      if (c.tTest)
        table.rows.push_back({dv.dv, c.description, "t(" + analysis::formatNumber(c.tTest->df) + ") = " + analysis::formatNumber(c.tTest->t),
                              analysis::formatP(c.tTest->p)});
      if (c.wilcoxon) table.rows.push_back({dv.dv, c.factor + " Wilcoxon", "V = " + analysis::formatNumber(c.wilcoxon->V), analysis::formatP(c.wilcoxon->p)});
      if (c.friedman)
        table.rows.push_back({dv.dv, c.factor + " Friedman", "chi2 = " + analysis::formatNumber(c.friedman->chiSquared), analysis::formatP(c.friedman->p)});
      if (c.mannWhitney) table.rows.push_back({dv.dv, c.factor + " Mann-Whitney", "W = " + analysis::formatNumber(c.mannWhitney->W), analysis::formatP(c.mannWhitney->p)});
      if (!c.error.empty()) table.rows.push_back({dv.dv, c.factor, c.error, ""});
    }
  }
  const bool adjusted = a.spec.correction != "none";
  for (const auto& p : a.pairwise)
    table.rows.push_back({p.dv, p.factor + ": " + p.first + " vs " + p.second + " (paired" + (adjusted ? ", " + a.spec.correction + "-adjusted p" : "") + ")",
                          "t(" + analysis::formatNumber(p.test.df) + ") = " + analysis::formatNumber(p.test.t),
                          analysis::formatP(adjusted ? p.pAdjusted : p.test.p)});
  out += analysis::renderPlainText(table);
  for (const auto& m : a.mixed) {
    out += "\n-- " + m.dv + ": " + m.result.description() + "\n" + analysis::fitSummaryLine(m.result) + "\n";
    for (const auto& w : m.result.warnings) out += "warning: " + w + "\n";
    out += analysis::renderPlainText(analysis::fixedEffectsTable(m.result));
    out += analysis::renderPlainText(analysis::randomEffectsTable(m.result));
  }
  for (const auto& e : a.errors) out += "note: " + e + "\n";
  return out;
}

}  // namespace tlab::app
