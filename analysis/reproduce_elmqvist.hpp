#pragma once
// Reproduction of Elmqvist, Assarsson & Tsigas, "Dynamic transparency for 3D visualization: design
// and evaluation" (seed 004), Sec. VII: every reported F(1,15) with its p (overall completion time,
// Table 3 times for T1-T4, relative errors, T3 error distance), the 2 × 2 × 16 × 3 design count,
// and, for each F reported with means and SDs, the within-subject correlation it implies.
//
// With two within-subject levels, F(1, n-1) = t² of the paired t-test on the n subject means:
//   t = d̄ / (s_d/√n),  s_d² = s1² + s2² - 2 r s1 s2,
// so from the two means, the two SDs and F:  s_d = |m1 - m2| √n / √F  and
//   r = (s1² + s2² - s_d²) / (2 s1 s2).
// This assumes the reported SDs are those of the n = 16 subject means that entered the ANOVA; an r
// outside [-1, 1] would prove that they are not (or that F is wrong).
#include <optional>
#include <string>
#include <vector>

#include "analysis/interval.hpp"
#include "analysis/statcheck.hpp"

namespace tlab::analysis {

struct ElmqvistFTest {
  std::string measure;   // "completion time, all tasks"
  std::string location;  // where in the seed text
  ReportedValue meanInactive, sdInactive, meanActive, sdActive;
  ReportedValue F;
  PRelation pRelation = PRelation::Equal;
  ReportedValue p;  // for Table 3 stars: "*" → p < .05, "**" → p < .01
};

struct ElmqvistFCheck {
  ElmqvistFTest published;
  double df1 = 1, df2 = 15;
  double pComputed = 0.0;  // P(F_{1,15} > F) at the printed F
  Interval pRange;         // over the rounding interval of F
  bool pConsistent = false;
  double impliedCorrelation = 0.0;
  Interval impliedCorrelationRange;
  bool correlationPossible = false;  // the range meets [-1, 1]
};

struct ElmqvistReproduction {
  std::vector<ElmqvistFCheck> fTests;
  // Design count: 2 (transparency) × 2 (scenario) × 16 participants × 3 trials.
  int designCount = 0;
  int reportedTaskCount = 384;
  int tasksPerScenario = 2;
  std::vector<std::string> findings;
};

std::vector<ElmqvistFTest> elmqvistReportedFTests();
ElmqvistReproduction reproduceElmqvist();

// Implied within-subject correlation from two means, two SDs and F(1, n-1); see the file comment.
double impliedWithinSubjectCorrelation(double mean1, double sd1, double mean2, double sd2, double F, double n);

}  // namespace tlab::analysis
