#pragma once
// Which t-test produced a published result? From the printed means, variances and group sizes we
// recompute t, df and p under the Welch, Student and paired hypotheses, carry the rounding of every
// printed decimal through interval arithmetic (analysis/interval.hpp), and say which hypotheses
// reproduce the printed df, |t| and p. Used for Carnecky et al.'s Table 1 (reproduce_carnecky.hpp)
// and for any table given as CSV (reproduce_table.hpp).
#include <optional>
#include <string>

#include "analysis/interval.hpp"
#include "analysis/ttest.hpp"

namespace tlab::analysis {

// One printed two-group comparison.
struct PrintedTTest {
  ReportedValue mean1, mean2;
  double variance1 = 0.0, variance2 = 0.0;   // at the printed values
  Interval variance1Range, variance2Range;   // over their rounding (a printed variance, or an SD squared)
  double n1 = 0.0, n2 = 0.0;
  std::optional<ReportedValue> df, t, p;  // as printed; a missing one is not checked
  int pTails = 2;                         // the printed p is one- or two-sided
};

// What one test hypothesis predicts for one comparison.
struct TTestHypothesisCheck {
  TTestKind kind = TTestKind::Welch;
  double t = 0.0;              // at the printed values (paired: not determined, NaN)
  double df = 0.0;
  double pOneSided = 0.0;      // P(T < -|t|)
  Interval absTRange;          // |t| over the rounding box of the inputs
  Interval dfRange;
  Interval pRange;             // enclosure of p with the printed number of tails
  bool dfConsistent = false;   // range meets the printed df's rounding interval (true if not printed)
  bool tConsistent = false;    // |t| range meets the printed |t|'s interval (true if not printed)
  bool pConsistent = false;
  bool consistent() const { return dfConsistent && tConsistent && pConsistent; }
  // Paired only: the correlation between the two conditions that the printed |t| would need
  // (r = (s1² + s2² - n·d̄²/t²)/(2 s1 s2)), with its range over the rounding box.
  double impliedCorrelation = 0.0;
  Interval impliedCorrelationRange;
};

// Welch or Student (pooled variance).
TTestHypothesisCheck checkTwoSampleHypothesis(const PrintedTTest& c, TTestKind kind);
// Paired: needs n1 = n2 (= n); df = n - 1 whatever the data, t depends on the unreported r.
TTestHypothesisCheck checkPairedHypothesis(const PrintedTTest& c);

}  // namespace tlab::analysis
