#include "analysis/reproduce_carnecky.hpp"

#include <cmath>
#include <sstream>

#include "analysis/distributions.hpp"

namespace tlab::analysis {

std::vector<CarneckyComparison> carneckyTable1() {
  // Carnecky, Fuchs, Mehl, Jang, Peikert, "Smart transparency for illustrative visualization of
  // complex flow surfaces", IEEE TVCG 19(5) 2013, Table 1 ("Comparison of the percentage of correct
  // answers ... using paired samples t-tests"), seed 000_30b23ea88644c383.txt lines 1255-1300.
  // The p quoted in the text is from Sec. 8.2 ("Study Results"), lines 1365-1374:
  // alpha blending vs normal variation p = 0.54, illustrative vs normal variation p = 0.005,
  // illustrative vs alpha blending p = 0.026. n = 36 students (line 1358).
  const auto v = [](const char* s) { return ReportedValue::parse(s); };
  return {
      {"Normal Variation", "Alpha Blending", v("0.234"), v("0.035"), v("0.264"), v("0.051"), v("68"),
       v("0.62"), v("0.270"), v("0.54"), 36},
      {"Alpha Blending", "Illustrative Transparency", v("0.264"), v("0.051"), v("0.382"), v("0.077"),
       v("67"), v("-1.98"), v("0.026"), v("0.026"), 36},
      {"Normal Variation", "Illustrative Transparency", v("0.234"), v("0.035"), v("0.382"), v("0.077"),
       v("61"), v("-2.66"), v("0.005"), v("0.005"), 36},
  };
}

PrintedTTest printedTTest(const CarneckyComparison& c) {
  PrintedTTest p;
  p.mean1 = c.mean1;
  p.mean2 = c.mean2;
  p.variance1 = c.variance1.value;
  p.variance2 = c.variance2.value;
  p.variance1Range = c.variance1.interval();
  p.variance2Range = c.variance2.interval();
  p.n1 = p.n2 = static_cast<double>(c.n);
  p.df = c.df;
  p.t = c.t;
  p.p = c.pOneSided;
  p.pTails = 1;
  return p;
}

namespace {

std::string fmt(double x, int precision = 3) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(precision);
  out << x;
  return out.str();
}

// One row of Table 1 checked as Welch, Student and paired tests, its sign and which sidedness
// the p quoted in the text has.
CarneckyRow checkRow(const CarneckyComparison& c) {
  CarneckyRow row;
  row.published = c;
  const PrintedTTest printed = printedTTest(c);
  row.checks.push_back(checkTwoSampleHypothesis(printed, TTestKind::Welch));
  row.checks.push_back(checkTwoSampleHypothesis(printed, TTestKind::Student));
  row.checks.push_back(checkPairedHypothesis(printed));
  row.signMatchesMeans = (c.t.value < 0) == (c.mean1.value < c.mean2.value);
  const Interval absT = row.checks[0].absTRange;
  const Interval df = row.checks[0].dfRange;
  row.pTwoSidedWelch = 2 * row.checks[0].pOneSided;
  const Interval twoSided{2 * studentTLowerTail(-absT.hi, df.hi), 2 * studentTLowerTail(-absT.lo, df.lo)};
  row.textPIsTwoSided = twoSided.intersects(c.pInText.interval());
  row.textPIsOneSided = row.checks[0].pRange.intersects(c.pInText.interval());
  return row;
}

// Which test the table's numbers come from: Welch for every row, Student or paired for any.
void addTestFindings(CarneckyReproduction& out, bool welchAll, bool studentAny, bool pairedAny) {
  out.findings.push_back(
      welchAll ? "Welch's unequal-variance t-test (Welch-Satterthwaite df) reproduces every printed df, |t| and "
                 "one-sided p within the rounding of the printed decimals."
               : "Welch's test does NOT reproduce every printed value.");
  out.findings.push_back(studentAny ? "Student's pooled t-test is consistent with at least one row."
                                    : "Student's pooled t-test is excluded: its df is 2n - 2 = 70, not 68/67/61 "
                                      "(its t equals Welch's because n1 = n2).");
  out.findings.push_back(
      pairedAny ? "A paired t-test is consistent with at least one row."
                : "A paired t-test is excluded: its df would be n - 1 = 35. Read as paired tests, the printed t "
                  "would need a correlation between methods of r = " +
                      fmt(out.rows[0].checks[2].impliedCorrelation) + ", " +
                      fmt(out.rows[1].checks[2].impliedCorrelation) + ", " +
                      fmt(out.rows[2].checks[2].impliedCorrelation) +
                      ", i.e. about 0: the numbers are independent-samples statistics although the table caption "
                      "says paired and every participant saw all three methods.");
}

// A row's own slips: a t with the wrong sign, significance only one-sided, a two-sided p in the text.
void addRowFindings(CarneckyReproduction& out, const CarneckyRow& row) {
  if (!row.signMatchesMeans)
    out.findings.push_back("Row '" + row.published.first + " vs " + row.published.second + "': printed t = " +
                           row.published.t.text + " has the opposite sign of mean1 - mean2 (" +
                           row.published.mean1.text + " - " + row.published.mean2.text +
                           "); its p = " + row.published.pOneSided.text +
                           " is the one-sided p of -|t|, so the sign is a transcription/ordering slip.");
  if (row.textPIsOneSided && row.published.pOneSided.value < 0.05 && row.pTwoSidedWelch >= 0.05)
    out.findings.push_back("'" + row.published.first + " vs " + row.published.second + "' is significant only "
                           "one-sided: the text's p = " + row.published.pInText.text +
                           " is one-sided; the two-sided Welch p is " + fmt(row.pTwoSidedWelch) + ".");
  if (row.textPIsTwoSided && !row.textPIsOneSided)
    out.findings.push_back("The text's p = " + row.published.pInText.text + " for '" + row.published.first +
                           " vs " + row.published.second + "' is the two-sided Welch p (" +
                           fmt(row.pTwoSidedWelch) + "), while the other comparisons quote one-sided p.");
}

}  // namespace

CarneckyReproduction reproduceCarnecky() {
  CarneckyReproduction out;
  bool welchAll = true;
  bool studentAny = false;
  bool pairedAny = false;
  for (const auto& c : carneckyTable1()) {
    out.rows.push_back(checkRow(c));
    const CarneckyRow& row = out.rows.back();
    welchAll = welchAll && row.checks[0].consistent();
    studentAny = studentAny || row.checks[1].consistent();
    pairedAny = pairedAny || row.checks[2].consistent();
  }
  addTestFindings(out, welchAll, studentAny, pairedAny);
  for (const auto& row : out.rows) addRowFindings(out, row);
  out.findings.push_back(
      "The layout (mean, variance, df rounded to an integer, 't Stat', 'P(T<=t) one-tail') matches a "
      "spreadsheet 't-Test: Two-Sample Assuming Unequal Variances' output, which would explain Welch numbers "
      "under a 'paired' caption (a plausible explanation, not a verified one).");
  return out;
}

}  // namespace tlab::analysis
