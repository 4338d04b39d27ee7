#pragma once
// Pairwise comparisons of the levels of a within-subject factor: per subject the mean of the
// dependent variable at each level (R's mean), then a paired t-test between every two levels on
// the subjects who have both — the follow-up tests of a factor with more than two levels.
#include <optional>
#include <string>
#include <vector>

#include "analysis/table.hpp"
#include "analysis/ttest.hpp"

namespace tlab::analysis {

struct PairwiseComparison {
  std::string first, second;  // level names, in the order given
  std::optional<TTestResult> test;
  std::string error;  // why there is no test (too few subjects, constant differences)
};

std::vector<PairwiseComparison> pairwisePairedTTests(const Table& table, const std::string& subject, const std::string& factor,
                                                     const std::vector<std::string>& levels, const std::string& dv, double confidence);

}  // namespace tlab::analysis
