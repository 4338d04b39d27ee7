#include "analysis/likert_summary.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/analysis_error.hpp"
#include "analysis/descriptives.hpp"
#include "analysis/number_format.hpp"
#include "analysis/r_moments.hpp"

namespace tlab::analysis {

namespace {

LikertItemSummary summarize(std::string group, std::string item, std::vector<double> values, int points) {
  LikertItemSummary s;
  s.group = std::move(group);
  s.item = std::move(item);
  s.n = values.size();
  s.mean = rMean(values);
  s.sd = values.size() > 1 ? std::sqrt(rVariance(values)) : std::nan("");
  s.counts.assign(static_cast<std::size_t>(points), 0);
  for (const double v : values) ++s.counts[static_cast<std::size_t>(v) - 1];
  std::sort(values.begin(), values.end());
  s.q1 = quantileType7(values, 0.25);
  s.median = quantileType7(values, 0.5);
  s.q3 = quantileType7(values, 0.75);
  return s;
}

}  // namespace

std::vector<LikertItemSummary> summarizeLikert(const Table& table, const std::string& groupColumn,
                                               const std::string& itemColumn, const std::string& valueColumn,
                                               int points) {
  if (points < 2) throw AnalysisError("a rating scale needs at least 2 points, got " + std::to_string(points));
  const std::size_t g = table.columnIndex(groupColumn), i = table.columnIndex(itemColumn), v = table.columnIndex(valueColumn);
  std::vector<std::pair<std::string, std::string>> order;
  std::map<std::pair<std::string, std::string>, std::vector<double>> values;
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    const double value = table.number(r, v);
    if (value != std::floor(value) || value < 1 || value > points)
      throw AnalysisError(table.where(r) + ": column '" + valueColumn + "': " + table.text(r, v) +
                          " is not a point of the 1.." + std::to_string(points) + " scale");
    const std::pair key{table.text(r, g), table.text(r, i)};
    if (!values.count(key)) order.push_back(key);
    values[key].push_back(value);
  }
  std::vector<LikertItemSummary> out;
  for (const auto& key : order) out.push_back(summarize(key.first, key.second, values[key], points));
  return out;
}

TextTable likertTable(const std::vector<LikertItemSummary>& items, int points, const std::string& caption) {
  TextTable t;
  t.caption = caption;
  t.header = {"questionnaire", "item", "n", "median", "IQR", "mean", "sd"};
  for (int k = 1; k <= points; ++k) t.header.push_back(std::to_string(k));
  for (const auto& s : items) {
    std::vector<std::string> row = {s.group, s.item, std::to_string(s.n), formatNumber(s.median),
                                    formatNumber(s.q1) + "-" + formatNumber(s.q3), formatNumber(s.mean),
                                    std::isnan(s.sd) ? "" : formatNumber(s.sd)};
    for (const std::size_t c : s.counts) row.push_back(std::to_string(c));
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace tlab::analysis
