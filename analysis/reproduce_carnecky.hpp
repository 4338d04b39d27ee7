#pragma once
// Reproduction of Carnecky et al. 2013 (seed 000), Table 1: three comparisons of the proportion of
// correct answers (n = 36 per method) reported as "paired samples t-tests" with degrees of freedom,
// t and one-sided p. From the published means and variances we recompute t, df and the one-sided
// p under the Welch, Student and paired hypotheses, carry the rounding of every printed decimal
// through interval arithmetic, and say which hypothesis the printed numbers are consistent with.
#include <string>
#include <vector>

#include "analysis/interval.hpp"
#include "analysis/ttest.hpp"
#include "analysis/ttest_reproduction.hpp"

namespace tlab::analysis {

struct CarneckyComparison {
  std::string first;   // column label in Table 1, e.g. "Normal Variation"
  std::string second;
  ReportedValue mean1, variance1, mean2, variance2;
  ReportedValue df, t, pOneSided;  // as printed
  ReportedValue pInText;           // the p quoted for this comparison in Sec. 8.2
  std::size_t n = 36;              // participants, every one in every condition (Sec. 8.2)
};

// What one test hypothesis predicts for one comparison (analysis/ttest_reproduction.hpp).
using CarneckyHypothesisCheck = TTestHypothesisCheck;

struct CarneckyRow {
  CarneckyComparison published;
  std::vector<CarneckyHypothesisCheck> checks;  // Welch, Student, paired
  bool signMatchesMeans = true;   // printed t has the sign of mean1 - mean2
  double pTwoSidedWelch = 0.0;    // to compare with the p quoted in the text
  bool textPIsTwoSided = false;   // text p matches the two-sided Welch p within rounding
  bool textPIsOneSided = false;
};

struct CarneckyReproduction {
  std::vector<CarneckyRow> rows;
  std::vector<std::string> findings;  // plain-language conclusions
};

// The values of Table 1 as printed (typed in from seed 000, lines ~1255-1300).
std::vector<CarneckyComparison> carneckyTable1();
// A comparison as the generic reproduction reads it (the printed p is one-sided).
PrintedTTest printedTTest(const CarneckyComparison& c);
CarneckyReproduction reproduceCarnecky();

}  // namespace tlab::analysis
