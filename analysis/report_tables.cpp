#include "analysis/report_tables.hpp"

#include "analysis/number_format.hpp"

namespace tlab::analysis {

namespace {

std::string levelList(const FactorLevels& f) {
  std::string s;
  for (const auto& l : f.levels) s += (s.empty() ? "" : ", ") + l;
  return s;
}

std::string ci(double lo, double hi) {
  std::string s(1, '[');
  s += formatNumber(lo);
  s += ", ";
  s += formatNumber(hi);
  s += ']';
  return s;
}

}  // namespace

TextTable designTable(const Report& report) {
  TextTable t;
  t.caption = "Design";
  t.header = {"item", "value"};
  t.rows.push_back({"data", report.source + " (" + std::to_string(report.design.rows) + " rows)"});
  t.rows.push_back({"subjects", std::to_string(report.design.subjects) +
                                    (report.design.subject.empty() ? " (one per row)" : " (column '" + report.design.subject + "')")});
  for (const auto& f : report.design.between)
    t.rows.push_back({"between: " + f.name, std::to_string(f.levels.size()) + " levels: " + levelList(f)});
  for (const auto& f : report.design.within)
    t.rows.push_back({"within: " + f.name, std::to_string(f.levels.size()) + " levels: " + levelList(f)});
  std::string dvs;
  for (const auto& dv : report.plan.dependentVariables) dvs += (dvs.empty() ? "" : ", ") + dv;
  t.rows.push_back({"dependent variables", dvs});
  if (report.design.maxReplicates > 1)
    t.rows.push_back({"replicates", "up to " + std::to_string(report.design.maxReplicates) +
                                        " per subject and cell, averaged"});
  return t;
}

TextTable descriptivesTable(const DependentVariableReport& dv) {
  TextTable t;
  t.caption = "Descriptives of " + dv.dv + " per cell (over subjects)";
  t.header = {"cell", "n", "mean", "sd", "var", "se", "95% CI", "median"};
  for (const auto& c : dv.cells) {
    if (!c.stats) {
      t.rows.push_back({c.label, std::to_string(c.values.size()), c.values.empty() ? "NA" : formatNumber(c.values[0]),
                        "NA", "NA", "NA", c.error, "NA"});
      continue;
    }
    const auto& d = *c.stats;
    t.header[6] = formatNumber(d.confidence * 100, 3) + "% CI";
    t.rows.push_back({c.label, std::to_string(d.n), formatNumber(d.mean), formatNumber(d.sd), formatNumber(d.variance),
                      formatNumber(d.se), ci(d.ciLow, d.ciHigh), formatNumber(d.median)});
  }
  return t;
}

TextTable outlierTable(const DependentVariableReport& dv) {
  TextTable t;
  t.caption = "Outlier screening of " + dv.dv;
  t.header = {"cell", "subject", "value", "z", "rule"};
  for (const auto& c : dv.cells)
    for (const auto& o : c.outliers.outliers)
      t.rows.push_back({c.label, c.subjects[o.index], formatNumber(o.value), formatNumber(o.z, 3),
                        std::string(outlierRuleName(o.rule))});
  return t;
}

TextTable anovaTable(const AnovaResult& anova) {
  TextTable t;
  t.caption = "ANOVA (type " + std::string(sumOfSquaresTypeName(anova.ssType)) + " sums of squares, " +
              std::to_string(anova.subjects) + " subjects)";
  t.header = {"effect", "df1", "df2", "SS", "SS error", "F", "p", "eta2 partial", "eta2 generalized"};
  for (const auto& e : anova.effects)
    t.rows.push_back({e.name, formatNumber(e.df1), formatNumber(e.df2), formatNumber(e.ss), formatNumber(e.ssError),
                      formatNumber(e.F), formatP(e.p), formatNumber(e.eta2Partial, 3),
                      formatNumber(e.eta2Generalized, 3)});
  return t;
}

TextTable sphericityTable(const AnovaResult& anova) {
  TextTable t;
  t.caption = "Sphericity (Mauchly's test; Greenhouse-Geisser and Huynh-Feldt corrections)";
  t.header = {"effect", "Mauchly W", "p", "eps GG", "p GG", "eps HF", "p HF"};
  for (const auto& e : anova.effects)
    if (e.sphericity)
      t.rows.push_back({e.name, formatNumber(e.sphericity->mauchlyW), formatP(e.sphericity->mauchlyP),
                        formatNumber(e.sphericity->epsilonGG), formatP(e.pGG), formatNumber(e.sphericity->epsilonHF),
                        formatP(e.pHF)});
  return t;
}

TextTable comparisonTable(const std::vector<Comparison>& comparisons) {
  TextTable t;
  t.caption = "Two-condition and rank tests (marginal subject means)";
  t.header = {"comparison", "test", "statistic", "df", "p", "effect size"};
  for (const auto& c : comparisons) {
    if (!c.error.empty()) t.rows.push_back({c.description.empty() ? c.factor : c.description, "error", c.error, "", "", ""});
    if (c.tTest)
      t.rows.push_back({c.description, std::string(tTestKindName(c.tTest->kind)) + " t-test",
                        "t = " + formatNumber(c.tTest->t), formatNumber(c.tTest->df), formatP(c.tTest->p),
                        (c.tTest->kind == TTestKind::Paired ? "d_z = " : "d = ") + formatNumber(c.tTest->cohensD, 3)});
    if (c.wilcoxon)
      t.rows.push_back({c.description, std::string("Wilcoxon signed-rank") + (c.wilcoxon->exact ? " (exact)" : " (normal approx.)"),
                        "V = " + formatNumber(c.wilcoxon->V), "", formatP(c.wilcoxon->p), ""});
    if (c.mannWhitney)
      t.rows.push_back({c.description, std::string("Mann-Whitney") + (c.mannWhitney->exact ? " (exact)" : " (normal approx.)"),
                        "W = " + formatNumber(c.mannWhitney->W), "", formatP(c.mannWhitney->p), ""});
    if (c.friedman)
      t.rows.push_back({c.description, "Friedman", "chi2 = " + formatNumber(c.friedman->chiSquared),
                        formatNumber(c.friedman->df), formatP(c.friedman->p), ""});
  }
  return t;
}

TextTable tTestTable(const TTestResult& r) {
  TextTable t;
  t.caption = std::string(tTestKindName(r.kind)) + " t-test (alternative: " + std::string(alternativeName(r.alternative)) + ")";
  t.header = {"t", "df", "p", "mean diff", formatNumber(r.confidence * 100, 3) + "% CI", "d", "Hedges g"};
  t.rows.push_back({formatNumber(r.t, 6), formatNumber(r.df, 6), formatP(r.p), formatNumber(r.meanDiff, 6),
                    ci(r.ciLow, r.ciHigh), formatNumber(r.cohensD), formatNumber(r.hedgesG)});
  return t;
}

TextTable friedmanTable(const FriedmanResult& f) {
  TextTable t;
  t.caption = "Friedman rank sum test (" + std::to_string(f.blocks) + " subjects, " + std::to_string(f.treatments) +
              " conditions)";
  t.header = {"chi2", "df", "p"};
  t.rows.push_back({formatNumber(f.chiSquared, 6), formatNumber(f.df), formatP(f.p)});
  return t;
}

TextTable wilcoxonTable(const WilcoxonSignedRankResult& w) {
  TextTable t;
  t.caption = std::string("Wilcoxon signed-rank test, ") +
              (w.exact ? "exact" : "normal approximation with tie and continuity correction") + " (" +
              std::to_string(w.n) + " non-zero differences, " + std::to_string(w.zeros) + " zeros dropped)";
  t.header = {"V", "p"};
  t.rows.push_back({formatNumber(w.V, 6), formatP(w.p)});
  return t;
}

TextTable mannWhitneyTable(const MannWhitneyResult& m) {
  TextTable t;
  t.caption = std::string("Wilcoxon-Mann-Whitney rank sum test, ") +
              (m.exact ? "exact" : "normal approximation with tie and continuity correction") + " (n = " +
              std::to_string(m.nx) + " and " + std::to_string(m.ny) + ")";
  t.header = {"W", "p"};
  t.rows.push_back({formatNumber(m.W, 6), formatP(m.p)});
  return t;
}

TextTable pairwiseTable(const PairwiseResult& r) {
  TextTable t;
  t.caption = "Pairwise t-tests of " + r.factor + " (p adjusted: " + std::string(pAdjustName(r.adjust)) + ")";
  t.header = {"first", "second", "test", "t", "df", "mean diff", "p", "p adjusted"};
  for (const auto& row : r.rows) {
    if (!row.error.empty()) {
      t.rows.push_back({row.first, row.second, row.test, "-", "-", "-", "-", row.error});
      continue;
    }
    t.rows.push_back({row.first, row.second, row.test, formatNumber(row.t, 6), formatNumber(row.df, 6), formatNumber(row.meanDiff, 6),
                      formatP(row.p), formatP(row.pAdjusted)});
  }
  return t;
}

}  // namespace tlab::analysis
