#pragma once
// `tlab reproduce --table FILE.csv`: the question `tlab reproduce carnecky` answers for Carnecky
// et al.'s Table 1 — which t-test (Welch, Student, paired) produced the printed numbers? — for any
// paper's two-group comparisons, given as CSV (one row per comparison, numbers exactly as printed,
// so that their decimals carry their rounding):
//
//   first,second,mean1,var1,n1,mean2,var2,n2,df,t,p,p_tails
//   Normal Variation,Alpha Blending,0.234,0.035,36,0.264,0.051,36,68,0.62,0.270,1
//
// Required: mean1, mean2, n1, n2 and either var1, var2 (variances) or sd1, sd2 (standard
// deviations). Optional: first, second (labels), df, t, p (an empty or missing one is not checked)
// and p_tails (1 or 2, default 2). docs/reproduce-table.md documents it with Carnecky's table.
#include <string>
#include <vector>

#include "analysis/ttest_reproduction.hpp"

namespace tlab::analysis {

struct TableComparison {
  std::string first, second;  // labels
  std::string where;          // "file.csv:3"
  PrintedTTest printed;
  std::vector<TTestHypothesisCheck> checks;  // Welch, Student, paired (paired only when n1 = n2)
};

// Throws AnalysisError ("file:line: column 'x': ...") on a missing column or a bad cell.
std::vector<TableComparison> readComparisonTable(const std::string& path);  // checks left empty
std::vector<TableComparison> reproduceTable(const std::string& path);

}  // namespace tlab::analysis
