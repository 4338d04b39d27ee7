#include "analysis/pairwise_tests.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/analysis_error.hpp"
#include "analysis/factor.hpp"
#include "analysis/r_moments.hpp"

namespace tlab::analysis {

namespace {

// Per subject, the mean of `dv` at each level of `factor`.
std::map<std::string, std::map<std::string, double>> subjectLevelMeans(const Table& table, const std::string& subject,
                                                                       const std::string& factor, const std::string& dv) {
  const std::size_t s = table.columnIndex(subject), f = table.columnIndex(factor), y = table.columnIndex(dv);
  std::map<std::string, std::map<std::string, std::vector<double>>> values;
  for (std::size_t r = 0; r < table.rowCount(); ++r) values[table.text(r, s)][table.text(r, f)].push_back(table.number(r, y));
  std::map<std::string, std::map<std::string, double>> means;
  for (const auto& [who, levels] : values)
    for (const auto& [level, v] : levels) means[who][level] = rMean(v);
  return means;
}

// The levels to compare: as requested (each must occur), or R's factor() order.
std::vector<std::string> comparedLevels(const Table& table, const std::string& factor, const std::vector<std::string>& requested) {
  const Factor f = makeFactor(table, factor);
  if (requested.empty()) {
    requireLevelCount(f, 2, f.levels.size() + 2, "pairwise comparisons");
    return f.levels;
  }
  for (const auto& level : requested)
    if (std::find(f.levels.begin(), f.levels.end(), level) == f.levels.end())
      throw AnalysisError("level '" + level + "' of --levels does not occur in column '" + factor + "'");
  return requested;
}

// The values of each level: one per row, or one mean per subject when a subject column is given.
std::map<std::string, std::vector<double>> groupValues(const Table& table, const PairwiseRequest& request) {
  std::map<std::string, std::vector<double>> groups;
  if (!request.subject.empty()) {
    for (const auto& [who, byLevel] : subjectLevelMeans(table, request.subject, request.between, request.dv))
      for (const auto& [level, mean] : byLevel) groups[level].push_back(mean);
    return groups;
  }
  const std::size_t f = table.columnIndex(request.between), y = table.columnIndex(request.dv);
  for (std::size_t r = 0; r < table.rowCount(); ++r) groups[table.text(r, f)].push_back(table.number(r, y));
  return groups;
}

PairwiseRow pooledRow(const std::string& a, const std::string& b, const std::vector<double>& x, const std::vector<double>& y,
                      double pooledSd, double totalDf) {
  PairwiseRow row{a, b, "pooled-sd t"};
  row.meanDiff = rMean(x) - rMean(y);
  const double se = pooledSd * std::sqrt(1.0 / static_cast<double>(x.size()) + 1.0 / static_cast<double>(y.size()));
  row.t = row.meanDiff / se;
  row.df = totalDf;
  row.p = studentTPValue(row.t, totalDf, Alternative::TwoSided);
  return row;
}

PairwiseRow fromTest(const std::string& a, const std::string& b, const char* name, const TTestResult& r) {
  PairwiseRow row{a, b, name};
  row.t = r.t;
  row.df = r.df;
  row.meanDiff = r.meanDiff;
  row.p = r.p;
  return row;
}

PairwiseRow failedRow(const std::string& a, const std::string& b, const char* name, const std::string& error) {
  PairwiseRow row{a, b, name};
  row.t = row.df = row.meanDiff = row.p = std::nan("");
  row.error = error;
  return row;
}

std::vector<PairwiseRow> betweenRows(const Table& table, const PairwiseRequest& request, const std::vector<std::string>& levels) {
  const auto groups = groupValues(table, request);
  // pairwise.t.test with pool.sd: s_p² = Σ_g (n_g - 1) s_g² / Σ_g (n_g - 1) over all groups.
  double ss = 0.0, totalDf = 0.0;
  for (const auto& level : levels) {
    const auto& v = groups.at(level);
    if (v.size() < 2) continue;
    ss += rVariance(v) * static_cast<double>(v.size() - 1);
    totalDf += static_cast<double>(v.size() - 1);
  }
  const double pooledSd = std::sqrt(ss / totalDf);
  std::vector<PairwiseRow> rows;
  for (std::size_t i = 0; i < levels.size(); ++i)
    for (std::size_t j = i + 1; j < levels.size(); ++j) {
      const auto &x = groups.at(levels[i]), &y = groups.at(levels[j]);
      if (request.poolSd) {
        if (!(pooledSd > 0.0)) throw AnalysisError("zero pooled variance: every group of '" + request.between + "' is constant");
        rows.push_back(pooledRow(levels[i], levels[j], x, y, pooledSd, totalDf));
        continue;
      }
      try {
        rows.push_back(fromTest(levels[i], levels[j], "welch t", welchTTest(x, y, Alternative::TwoSided)));
      } catch (const AnalysisError& error) {
        rows.push_back(failedRow(levels[i], levels[j], "welch t", error.what()));
      }
    }
  return rows;
}

std::vector<PairwiseRow> withinRows(const Table& table, const PairwiseRequest& request, const std::vector<std::string>& levels) {
  std::vector<PairwiseRow> rows;
  for (const auto& c : pairwisePairedTTests(table, request.subject, request.within, levels, request.dv, 0.95))
    rows.push_back(c.test ? fromTest(c.first, c.second, "paired t", *c.test) : failedRow(c.first, c.second, "paired t", c.error));
  return rows;
}

}  // namespace

std::vector<PairwiseComparison> pairwisePairedTTests(const Table& table, const std::string& subject, const std::string& factor,
                                                     const std::vector<std::string>& levels, const std::string& dv, double confidence) {
  const auto means = subjectLevelMeans(table, subject, factor, dv);
  std::vector<PairwiseComparison> out;
  for (std::size_t a = 0; a < levels.size(); ++a)
    for (std::size_t b = a + 1; b < levels.size(); ++b) {
      std::vector<double> x, y;
      for (const auto& [who, byLevel] : means) {
        const auto la = byLevel.find(levels[a]), lb = byLevel.find(levels[b]);
        if (la == byLevel.end() || lb == byLevel.end()) continue;
        x.push_back(la->second);
        y.push_back(lb->second);
      }
      PairwiseComparison c{levels[a], levels[b], std::nullopt, ""};
      try {
        c.test = pairedTTest(x, y, Alternative::TwoSided, confidence);
      } catch (const AnalysisError& error) {
        c.error = error.what();
      }
      out.push_back(std::move(c));
    }
  return out;
}

PairwiseResult pairwiseTTestsOnTable(const Table& table, const PairwiseRequest& request) {
  if (request.within.empty() == request.between.empty())
    throw AnalysisError("pairwise comparisons need either --within (with --subject) or --between");
  if (!request.within.empty() && request.subject.empty())
    throw AnalysisError("--within needs --subject (the column naming the participant)");
  PairwiseResult result;
  result.factor = request.within.empty() ? request.between : request.within;
  result.adjust = request.adjust;
  const auto levels = comparedLevels(table, result.factor, request.levels);
  result.rows = request.within.empty() ? betweenRows(table, request, levels) : withinRows(table, request, levels);
  std::vector<double> p;
  for (const auto& row : result.rows) p.push_back(row.p);
  const std::vector<double> adjusted = pAdjust(p, request.adjust);
  for (std::size_t k = 0; k < result.rows.size(); ++k) result.rows[k].pAdjusted = adjusted[k];
  return result;
}

}  // namespace tlab::analysis
