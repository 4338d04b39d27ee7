#pragma once
// LikertSummary: the answers to rating-scale (Likert) items of a questionnaire, per item — how
// many answered, the median and quartiles (the ordinal summaries), the mean and SD (as papers
// report them, computed as R's mean and sd), and how often each scale point was chosen.
#include <string>
#include <vector>

#include "analysis/table.hpp"
#include "analysis/text_table.hpp"

namespace tlab::analysis {

struct LikertItemSummary {
  std::string group;  // e.g. the questionnaire
  std::string item;
  std::size_t n = 0;
  double mean = 0.0, sd = 0.0, median = 0.0, q1 = 0.0, q3 = 0.0;  // sd NaN for n < 2
  std::vector<std::size_t> counts;  // counts[k]: answers with value k + 1
};

// One summary per (group, item) in order of first appearance; values must be integers 1..points.
std::vector<LikertItemSummary> summarizeLikert(const Table& table, const std::string& groupColumn,
                                               const std::string& itemColumn, const std::string& valueColumn,
                                               int points);

TextTable likertTable(const std::vector<LikertItemSummary>& items, int points, const std::string& caption);

}  // namespace tlab::analysis
