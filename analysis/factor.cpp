#include "analysis/factor.hpp"

#include <algorithm>
#include <limits>
#include <map>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

Factor makeFactor(const Table& table, std::string_view column) {
  const std::size_t c = table.columnIndex(column);
  Factor factor;
  factor.name = std::string(column);
  std::vector<std::string> labels;
  for (std::size_t r = 0; r < table.rowCount(); ++r) labels.push_back(table.text(r, c));
  std::vector<std::string> levels = labels;
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  bool allNumeric = !levels.empty();
  std::map<std::string, double> numeric;
  for (const auto& level : levels) {
    double v = 0.0;
    if (!parseDouble(level, v)) {
      allNumeric = false;
      break;
    }
    numeric[level] = v;
  }
  if (allNumeric)
    std::stable_sort(levels.begin(), levels.end(),
                     [&](const std::string& a, const std::string& b) { return numeric[a] < numeric[b]; });
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < levels.size(); ++i) index[levels[i]] = i;
  factor.codes.reserve(labels.size());
  for (const auto& label : labels) factor.codes.push_back(index[label]);
  factor.levels = std::move(levels);
  return factor;
}

void requireLevelCount(const Factor& factor, std::size_t minLevels, std::size_t maxLevels,
                       std::string_view purpose) {
  const std::size_t k = factor.levels.size();
  if (k == 1 && minLevels >= 2)
    throw AnalysisError("factor '" + factor.name + "' has only one level ('" + factor.levels[0] +
                        "'): " + std::string(purpose) + " needs at least " +
                        std::to_string(minLevels) + " levels");
  if (k < minLevels)
    throw AnalysisError("factor '" + factor.name + "' has " + std::to_string(k) + " levels: " +
                        std::string(purpose) + " needs at least " + std::to_string(minLevels));
  if (k > maxLevels) {
    std::string list;
    for (const auto& l : factor.levels) list += (list.empty() ? "" : ", ") + l;
    throw AnalysisError("factor '" + factor.name + "' has " + std::to_string(k) + " levels (" + list +
                        "): " + std::string(purpose) + (minLevels == maxLevels ? " needs exactly " : " allows at most ") +
                        std::to_string(maxLevels));
  }
}

}  // namespace tlab::analysis
