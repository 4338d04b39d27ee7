#include "analysis/table_tests.hpp"

#include "analysis/analysis_error.hpp"
#include "analysis/anova_design.hpp"
#include "analysis/factor.hpp"

namespace tlab::analysis {

namespace {

struct TwoGroups {
  std::string names[2];
  std::vector<double> values[2];
};

TwoGroups splitByTwoLevelFactor(const Table& table, const std::string& dv, const std::string& between,
                                const char* purpose) {
  const std::vector<double> values = table.numericColumn(dv);
  const Factor factor = makeFactor(table, between);
  requireLevelCount(factor, 2, 2, purpose);
  TwoGroups groups;
  for (std::size_t i = 0; i < 2; ++i) groups.names[i] = between + "=" + factor.levels[i];
  for (std::size_t r = 0; r < values.size(); ++r) groups.values[factor.codes[r]].push_back(values[r]);
  return groups;
}

// Subject × level matrix of a within factor (balanced; replicates averaged).
AnovaDesign withinDesign(const Table& table, const std::string& dv, const std::string& within,
                         const std::string& subject) {
  if (within.empty() || subject.empty()) throw AnalysisError("a within-subject test needs --within and --subject");
  return makeAnovaDesign(table, dv, {}, {within}, subject);
}

std::vector<double> column(const AnovaDesign& d, Eigen::Index c) {
  std::vector<double> v(static_cast<std::size_t>(d.y.rows()));
  for (Eigen::Index r = 0; r < d.y.rows(); ++r) v[static_cast<std::size_t>(r)] = d.y(r, c);
  return v;
}

void requireTwoLevels(const AnovaDesign& d, const char* purpose) {
  const auto& f = d.within.front();
  if (f.levels.size() != 2) {
    std::string list;
    for (const auto& l : f.levels) list += (list.empty() ? "" : ", ") + l;
    throw AnalysisError("factor '" + f.name + "' has " + std::to_string(f.levels.size()) + " levels (" + list +
                        "): " + purpose + " needs exactly 2");
  }
}

}  // namespace

TTestResult tTestOnTable(const Table& table, const TTestRequest& request) {
  if (!request.between.empty() && !request.within.empty())
    throw AnalysisError("give either --between (two-sample) or --within with --subject (paired), not both");
  if (!request.between.empty()) {
    const TwoGroups g = splitByTwoLevelFactor(table, request.dv, request.between, "a two-sample t-test");
    // Validated here so that errors name the group ("group condition=b has n = 1").
    summarizeSample(g.values[0], "group " + g.names[0]);
    summarizeSample(g.values[1], "group " + g.names[1]);
    return request.student ? studentTTest(g.values[0], g.values[1], request.alternative, request.confidence)
                           : welchTTest(g.values[0], g.values[1], request.alternative, request.confidence);
  }
  if (!request.within.empty()) {
    const AnovaDesign d = withinDesign(table, request.dv, request.within, request.subject);
    requireTwoLevels(d, "a paired t-test");
    return pairedTTest(column(d, 0), column(d, 1), request.alternative, request.confidence);
  }
  return oneSampleTTest(table.numericColumn(request.dv), request.mu, request.alternative, request.confidence);
}

FriedmanResult friedmanOnTable(const Table& table, const std::string& dv, const std::string& within,
                               const std::string& subject) {
  return friedmanTest(withinDesign(table, dv, within, subject).y);
}

WilcoxonSignedRankResult wilcoxonOnTable(const Table& table, const std::string& dv, const std::string& within,
                                         const std::string& subject, Alternative alternative) {
  const AnovaDesign d = withinDesign(table, dv, within, subject);
  requireTwoLevels(d, "the Wilcoxon signed-rank test");
  return wilcoxonSignedRankTest(column(d, 0), column(d, 1), 0.0, alternative);
}

MannWhitneyResult mannWhitneyOnTable(const Table& table, const std::string& dv, const std::string& between,
                                     Alternative alternative) {
  const TwoGroups g = splitByTwoLevelFactor(table, dv, between, "the Mann-Whitney test");
  return mannWhitneyTest(g.values[0], g.values[1], alternative);
}

}  // namespace tlab::analysis
