#include "analysis/reproduce_elmqvist.hpp"

#include <cmath>
#include <sstream>

#include "analysis/distributions.hpp"

namespace tlab::analysis {

std::vector<ElmqvistFTest> elmqvistReportedFTests() {
  // Typed in from seed 004_5a2d71233f7987a3.txt, Sec. VII (Results):
  //  - VII.1, line 460: overall completion time 65.17 (s.d. 27.75) inactive vs 28.69 (s.d. 11.02)
  //    active, F(1,15) = 49.54, p < .001;
  //  - Table 3, lines 462-470: T1 56.26 (38.72) / 40.44 (20.99) F 7.54 *; T2 22.30 (16.20) /
  //    15.80 (10.21) F 5.28 *; T3 62.78 (35.63) / 23.21 (12.01) F 22.98 **; T4 140.0 (61.75) /
  //    40.80 (24.16) F 48.61 **, with * = p < 0.05 and ** = p < 0.01; the df are those of the
  //    text, (1, 15);
  //  - VII.2, line 474: relative error T1+T4 .100 (.141) / .027 (.045), F(1, 15) = 6.28, p = .024;
  //  - line 476: T1 .042 (.046) / .017 (.018), F(1,15) = 4.74, p = .046; T4 .123 (.184) /
  //    .034 (.074), F(1,15) = 4.12, p = .061;
  //  - line 486: T3 error distance 16.99 (14.44) / 16.21 (8.88), F(1,15) = .068, p = .797.
  const auto v = [](const char* s) { return ReportedValue::parse(s); };
  const auto L = PRelation::Less;
  const auto E = PRelation::Equal;
  return {
      {"completion time, all tasks (s)", "Sec. VII.1", v("65.17"), v("27.75"), v("28.69"), v("11.02"), v("49.54"), L, v(".001")},
      {"completion time T1 (s)", "Table 3", v("56.26"), v("38.72"), v("40.44"), v("20.99"), v("7.54"), L, v(".05")},
      {"completion time T2 (s)", "Table 3", v("22.30"), v("16.20"), v("15.80"), v("10.21"), v("5.28"), L, v(".05")},
      {"completion time T3 (s)", "Table 3", v("62.78"), v("35.63"), v("23.21"), v("12.01"), v("22.98"), L, v(".01")},
      {"completion time T4 (s)", "Table 3", v("140.0"), v("61.75"), v("40.80"), v("24.16"), v("48.61"), L, v(".01")},
      {"relative error T1+T4", "Sec. VII.2", v(".100"), v(".141"), v(".027"), v(".045"), v("6.28"), E, v(".024")},
      {"relative error T1", "Sec. VII.2", v(".042"), v(".046"), v(".017"), v(".018"), v("4.74"), E, v(".046")},
      {"relative error T4", "Sec. VII.2", v(".123"), v(".184"), v(".034"), v(".074"), v("4.12"), E, v(".061")},
      {"error distance T3 (world units)", "Sec. VII.2", v("16.99"), v("14.44"), v("16.21"), v("8.88"), v(".068"), E, v(".797")},
  };
}

double impliedWithinSubjectCorrelation(double mean1, double sd1, double mean2, double sd2, double F, double n) {
  const double d = mean1 - mean2;
  const double sd2diff = d * d * n / F;
  return (sd1 * sd1 + sd2 * sd2 - sd2diff) / (2 * sd1 * sd2);
}

namespace {

std::string fmt(double x, int precision) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(precision);
  out << x;
  return out.str();
}

ElmqvistFCheck check(const ElmqvistFTest& t) {
  constexpr double n = 16;  // participants (Sec. VI.2)
  ElmqvistFCheck c;
  c.published = t;
  c.df1 = 1;
  c.df2 = n - 1;
  c.pComputed = fisherFUpperTail(t.F.value, c.df1, c.df2);
  const Interval F = t.F.interval();
  c.pRange = mapDecreasing(F, [&](double f) { return fisherFUpperTail(f, c.df1, c.df2); });
  c.pConsistent = reportedPConsistent(c.pRange, t.pRelation, t.p);  // statcheck.hpp rules
  c.impliedCorrelation = impliedWithinSubjectCorrelation(t.meanInactive.value, t.sdInactive.value,
                                                         t.meanActive.value, t.sdActive.value, t.F.value, n);
  const Interval s1 = t.sdInactive.interval();
  const Interval s2 = t.sdActive.interval();
  const Interval sdDiff2 = Interval::point(n) * square(t.meanInactive.interval() - t.meanActive.interval()) / F;
  c.impliedCorrelationRange = (square(s1) + square(s2) - sdDiff2) / (Interval::point(2.0) * s1 * s2);
  c.correlationPossible = c.impliedCorrelationRange.intersects({-1.0, 1.0});
  return c;
}

}  // namespace

ElmqvistReproduction reproduceElmqvist() {
  ElmqvistReproduction out;
  for (const auto& t : elmqvistReportedFTests()) out.fTests.push_back(check(t));
  // Sec. VI.6, line 433-438: "2 × 2 within-subjects design", "16 participants and 3 trials per
  // condition, there were 384 tasks recorded in total".
  out.designCount = 2 * 2 * 16 * 3;
  int consistent = 0;
  for (const auto& c : out.fTests) consistent += c.pConsistent ? 1 : 0;
  out.findings.push_back(std::to_string(consistent) + " of " + std::to_string(out.fTests.size()) +
                         " reported F(1,15) values agree with their reported p (or significance stars) within "
                         "the rounding of F.");
  for (const auto& c : out.fTests)
    if (!c.pConsistent)
      out.findings.push_back("INCONSISTENT: " + c.published.measure + ": F(1,15) = " + c.published.F.text +
                             " gives p = " + fmt(c.pComputed, 4) + ", reported p " +
                             std::string(pRelationSymbol(c.published.pRelation)) + " " + c.published.p.text);
  out.findings.push_back(
      "df (1, 15) with 16 participants means each test compares the two transparency levels within subjects "
      "(a repeated-measures ANOVA on subject means, F = paired t²); the paper's 'one-way ANOVA' would have "
      "df2 = 30 if the 16 + 16 means were treated as independent groups.");
  out.findings.push_back("Design count: 2 × 2 × 16 × 3 = " + std::to_string(out.designCount) +
                         " subject × condition × trial cells, but the paper reports " +
                         std::to_string(out.reportedTaskCount) + " tasks: 384 = 192 × 2 holds because each "
                         "scenario had two tasks (T1, T2 abstract; T3, T4 walkthrough), i.e. 2 × 2 × 2 × 16 × 3.");
  bool allPossible = true;
  for (const auto& c : out.fTests) allPossible = allPossible && c.correlationPossible;
  out.findings.push_back(
      allPossible ? "Every implied within-subject correlation lies in [-1, 1], so means, SDs and F are mutually "
                    "consistent if the SDs are those of the 16 subject means."
                  : "Some implied correlation lies outside [-1, 1]: those SDs cannot be the SDs of the subject "
                    "means that entered the F test.");
  out.findings.push_back(
      "Not checkable from the text: the Friedman tests (T2 correctness p = 1.0 with equal means .963/.963 is "
      "plausible; subjective ratings p < .05 / p < .01) report no statistic.");
  return out;
}

}  // namespace tlab::analysis
