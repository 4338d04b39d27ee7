#pragma once
// Pairwise comparisons of the levels of one factor, as R's pairwise.t.test + p.adjust:
//  - within (paired): per subject the mean of the dependent variable at each level (R's mean),
//    then a paired t-test between every two levels on the subjects who have both;
//  - between (independent groups): replicates averaged per subject first when a subject column is
//    given, then t-tests with the pooled SD of all groups (pairwise.t.test's default pool.sd =
//    TRUE: s_p² = Σ(n_g - 1)s_g² / Σ(n_g - 1), t = (x̄_i - x̄_j)/(s_p √(1/n_i + 1/n_j)),
//    df = Σ(n_g - 1)), or Welch's test for each pair with poolSd = false.
// The raw p-values are adjusted together (p_adjust.hpp).
#include <optional>
#include <string>
#include <vector>

#include "analysis/p_adjust.hpp"
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

struct PairwiseRequest {
  std::string dv;
  std::string within;   // paired comparisons of this factor (needs subject), or
  std::string between;  // independent-groups comparisons of this factor
  std::string subject;  // averages replicates per subject and level first
  std::vector<std::string> levels;  // order of the levels (default: R's factor() order)
  PAdjustMethod adjust = PAdjustMethod::Holm;
  bool poolSd = true;   // between only: pooled SD (R's default) or Welch per pair
};

struct PairwiseRow {
  std::string first, second;
  std::string test;  // "paired t", "pooled-sd t", "welch t"
  double t = 0.0, df = 0.0;
  double meanDiff = 0.0;  // mean(first) - mean(second) (paired: mean of the differences)
  double p = 0.0;         // NaN when the comparison could not be made (see error)
  double pAdjusted = 0.0;
  std::string error{};
};

struct PairwiseResult {
  std::string factor;
  PAdjustMethod adjust = PAdjustMethod::Holm;
  std::vector<PairwiseRow> rows;
};

PairwiseResult pairwiseTTestsOnTable(const Table& table, const PairwiseRequest& request);

}  // namespace tlab::analysis
