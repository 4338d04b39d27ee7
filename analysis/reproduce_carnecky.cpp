#include "analysis/reproduce_carnecky.hpp"

#include <cmath>
#include <limits>
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

namespace {

// One-sided p = P(T_df < -|t|); decreasing in |t|, and for a fixed negative t increasing as df
// falls (heavier tails), so the corners below enclose p over the whole box.
Interval oneSidedPRange(Interval absT, Interval df) {
  return {studentTLowerTail(-absT.hi, df.hi), studentTLowerTail(-absT.lo, df.lo)};
}

// Welch df for equal n: (n-1)(v1+v2)²/(v1²+v2²) = (n-1)·g(ρ), ρ = v2/v1, g(ρ) = (1+ρ)²/(1+ρ²),
// which rises on [0, 1] to its maximum 2 and falls after: its exact range over the box follows
// from the range of ρ (no interval-dependency overestimate).
Interval welchDfRangeEqualN(Interval v1, Interval v2, double n) {
  const auto g = [](double rho) { return (1 + rho) * (1 + rho) / (1 + rho * rho); };
  const Interval rho = v2 / v1;
  double lo = std::min(g(rho.lo), g(rho.hi));
  double hi = rho.contains(1.0) ? 2.0 : std::max(g(rho.lo), g(rho.hi));
  return {(n - 1) * lo, (n - 1) * hi};
}

CarneckyHypothesisCheck checkTwoSample(const CarneckyComparison& c, TTestKind kind) {
  const double n = static_cast<double>(c.n);
  const SampleSummary x{c.n, c.mean1.value, c.variance1.value};
  const SampleSummary y{c.n, c.mean2.value, c.variance2.value};
  const TTestResult r = kind == TTestKind::Welch
                            ? welchTTestFromSummaries(x, y, Alternative::Less)
                            : studentTTestFromSummaries(x, y, Alternative::Less);
  CarneckyHypothesisCheck check;
  check.kind = kind;
  check.t = r.t;
  check.df = r.df;
  check.pOneSided = studentTLowerTail(-std::fabs(r.t), r.df);
  // With n1 = n2 the Student and Welch t coincide: |d̄| / √((v1 + v2)/n).
  const Interval diff = abs(c.mean1.interval() - c.mean2.interval());
  const Interval varianceSum = c.variance1.interval() + c.variance2.interval();
  check.absTRange = diff / sqrt(varianceSum / Interval::point(n));
  check.dfRange = kind == TTestKind::Welch
                      ? welchDfRangeEqualN(c.variance1.interval(), c.variance2.interval(), n)
                      : Interval::point(2 * n - 2);
  check.pRange = oneSidedPRange(check.absTRange, check.dfRange);
  check.dfConsistent = check.dfRange.intersects(c.df.interval());
  check.tConsistent = check.absTRange.intersects(abs(c.t.interval()));
  check.pConsistent = check.pRange.intersects(c.pOneSided.interval());
  return check;
}

// Paired: df = n - 1 whatever the data; t = d̄/√((s1² + s2² - 2 r s1 s2)/n) depends on the
// correlation r, which the paper does not report, so only df can decide; we also give the r the
// printed t would require.
CarneckyHypothesisCheck checkPaired(const CarneckyComparison& c) {
  const double n = static_cast<double>(c.n);
  CarneckyHypothesisCheck check;
  check.kind = TTestKind::Paired;
  check.t = std::nan("");
  check.df = n - 1;
  check.dfRange = Interval::point(n - 1);
  check.absTRange = {0.0, std::numeric_limits<double>::infinity()};  // any |t|, for some r
  check.pRange = {0.0, 0.5};
  check.pOneSided = std::nan("");
  check.dfConsistent = check.dfRange.intersects(c.df.interval());
  check.tConsistent = true;
  check.pConsistent = true;
  const double d = c.mean1.value - c.mean2.value;
  const double t = c.t.value;
  check.impliedCorrelation = (c.variance1.value + c.variance2.value - n * d * d / (t * t)) /
                             (2 * std::sqrt(c.variance1.value * c.variance2.value));
  const Interval d2 = square(c.mean1.interval() - c.mean2.interval());
  const Interval t2 = square(c.t.interval());
  const Interval numerator = c.variance1.interval() + c.variance2.interval() - Interval::point(n) * d2 / t2;
  check.impliedCorrelationRange = numerator / (Interval::point(2.0) * sqrt(c.variance1.interval() * c.variance2.interval()));
  return check;
}

std::string fmt(double x, int precision = 3) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(precision);
  out << x;
  return out.str();
}

}  // namespace

CarneckyReproduction reproduceCarnecky() {
  CarneckyReproduction out;
  bool welchAll = true;
  bool studentAny = false;
  bool pairedAny = false;
  for (const auto& c : carneckyTable1()) {
    CarneckyRow row;
    row.published = c;
    row.checks.push_back(checkTwoSample(c, TTestKind::Welch));
    row.checks.push_back(checkTwoSample(c, TTestKind::Student));
    row.checks.push_back(checkPaired(c));
    welchAll = welchAll && row.checks[0].consistent();
    studentAny = studentAny || row.checks[1].consistent();
    pairedAny = pairedAny || row.checks[2].consistent();
    row.signMatchesMeans = (c.t.value < 0) == (c.mean1.value < c.mean2.value);
    const Interval absT = row.checks[0].absTRange;
    const Interval df = row.checks[0].dfRange;
    row.pTwoSidedWelch = 2 * row.checks[0].pOneSided;
    const Interval twoSided{2 * studentTLowerTail(-absT.hi, df.hi), 2 * studentTLowerTail(-absT.lo, df.lo)};
    row.textPIsTwoSided = twoSided.intersects(c.pInText.interval());
    row.textPIsOneSided = row.checks[0].pRange.intersects(c.pInText.interval());
    out.rows.push_back(row);
  }
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
  for (const auto& row : out.rows) {
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
  out.findings.push_back(
      "The layout (mean, variance, df rounded to an integer, 't Stat', 'P(T<=t) one-tail') matches a "
      "spreadsheet 't-Test: Two-Sample Assuming Unequal Variances' output, which would explain Welch numbers "
      "under a 'paired' caption (a plausible explanation, not a verified one).");
  return out;
}

}  // namespace tlab::analysis
