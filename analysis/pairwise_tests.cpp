#include "analysis/pairwise_tests.hpp"

#include <map>

#include "analysis/analysis_error.hpp"
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

}  // namespace tlab::analysis
