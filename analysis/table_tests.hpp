#pragma once
// The tests of `tlab stats` run on a long-format Table by column names: the columns are turned
// into groups (between) or a subject × condition matrix (within; balanced, replicates averaged,
// see anova_design.hpp) and handed to the tests. Levels are ordered like R's factor(), so "x" is
// the first level and e.g. mean_diff = mean(level 1) - mean(level 2), as R's t.test(dv ~ g).
#include <string>

#include "analysis/rank_tests.hpp"
#include "analysis/table.hpp"
#include "analysis/ttest.hpp"

namespace tlab::analysis {

struct TTestRequest {
  std::string dv;
  std::string between;  // two-sample test on this 2-level column, or
  std::string within;   // paired test on this 2-level column with
  std::string subject;  // the subject column; none of the three: one-sample test against mu
  bool student = false; // pooled variance instead of Welch (between only)
  Alternative alternative = Alternative::TwoSided;
  double mu = 0.0;
  double confidence = 0.95;
};

TTestResult tTestOnTable(const Table& table, const TTestRequest& request);
FriedmanResult friedmanOnTable(const Table& table, const std::string& dv, const std::string& within,
                               const std::string& subject);
WilcoxonSignedRankResult wilcoxonOnTable(const Table& table, const std::string& dv, const std::string& within,
                                         const std::string& subject, Alternative alternative);
MannWhitneyResult mannWhitneyOnTable(const Table& table, const std::string& dv, const std::string& between,
                                     Alternative alternative);

}  // namespace tlab::analysis
