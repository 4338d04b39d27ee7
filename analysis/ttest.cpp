#include "analysis/ttest.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string formatNumber(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

// A standard error of exactly zero makes t = meanDiff / 0: say so instead of printing inf/nan.
// Like R's t.test, a standard error below 10·eps·|mean| is refused too ("data are essentially
// constant"): the means themselves are not known to that precision.
void requireNonzeroStandardError(double se, double meanDiff, const std::string& what, double magnitude) {
  if (se > 0.0 && std::isfinite(se) && se < 10.0 * std::numeric_limits<double>::epsilon() * magnitude)
    throw AnalysisError("data are essentially constant: the standard error " + formatNumber(se) +
                        " is below 10·eps·|mean| = " +
                        formatNumber(10.0 * std::numeric_limits<double>::epsilon() * magnitude) +
                        ", so the means are not known to that precision (R's t.test refuses too); "
                        "subtract a constant from the data first");
  if (se > 0.0 && std::isfinite(se)) return;
  std::string consequence =
      meanDiff == 0.0 ? "t = 0/0 is undefined"
                      : std::string("t would be ") + (meanDiff > 0 ? "+" : "-") + "infinite";
  throw AnalysisError("zero variance: " + what + " (mean difference " + formatNumber(meanDiff) +
                      "), so " + consequence);
}

// Confidence interval as R's t.test computes it: mu + (t ± q)·se, where mu is the hypothesised
// value (the one-sample interval is of the mean itself, the two-sample one of the difference).
void setConfidenceInterval(TTestResult& r, double mu) {
  if (r.confidence <= 0.0 || r.confidence >= 1.0)
    throw AnalysisError("confidence level must lie in (0, 1), got " + formatNumber(r.confidence));
  switch (r.alternative) {
    case Alternative::TwoSided: {
      const double q = studentTQuantile(1.0 - (1.0 - r.confidence) / 2.0, r.df);
      r.ciLow = mu + (r.t - q) * r.se;
      r.ciHigh = mu + (r.t + q) * r.se;
      break;
    }
    case Alternative::Less:
      r.ciLow = -kInf;
      r.ciHigh = mu + (r.t + studentTQuantile(r.confidence, r.df)) * r.se;
      break;
    case Alternative::Greater:
      r.ciLow = mu + (r.t - studentTQuantile(r.confidence, r.df)) * r.se;
      r.ciHigh = kInf;
      break;
  }
}

void finish(TTestResult& r, double effectSizeDf, double mu = 0.0) {
  r.t = r.meanDiff / r.se;
  r.p = studentTPValue(r.t, r.df, r.alternative);
  setConfidenceInterval(r, mu);
  r.hedgesG = hedgesCorrection(effectSizeDf) * r.cohensD;
}

double pooledVariance(const SampleSummary& x, const SampleSummary& y) {
  const double n1 = static_cast<double>(x.n);
  const double n2 = static_cast<double>(y.n);
  return ((n1 - 1.0) * x.variance + (n2 - 1.0) * y.variance) / (n1 + n2 - 2.0);
}

void requireAtLeastTwo(const SampleSummary& s, const char* which) {
  if (s.n < 2)
    throw AnalysisError(std::string(which) + " has n = " + std::to_string(s.n) +
                        "; at least 2 observations are needed to estimate a variance");
}

using TwoSampleFromSummaries = TTestResult (*)(const SampleSummary&, const SampleSummary&, Alternative, double);

// R's t.test.default: mean(x) - mean(y) of the two means as R rounds them, var(x), var(y).
TTestResult twoSampleTTest(std::span<const double> x, std::span<const double> y, Alternative alternative,
                           double confidence, TwoSampleFromSummaries test) {
  return test(summarizeSample(x, "the first group"), summarizeSample(y, "the second group"), alternative, confidence);
}

}  // namespace

std::string_view tTestKindName(TTestKind kind) {
  switch (kind) {
    case TTestKind::OneSample: return "one-sample";
    case TTestKind::Paired: return "paired";
    case TTestKind::Student: return "student";
    case TTestKind::Welch: return "welch";
  }
  return "welch";
}

double hedgesCorrection(double m) {
  if (!(m > 0.0)) return std::nan("");
  if (m <= 1.0) return 0.0;  // Γ((m-1)/2) → ∞ at m = 1
  return std::exp(std::lgamma(m / 2.0) - std::lgamma((m - 1.0) / 2.0)) / std::sqrt(m / 2.0);
}

namespace {
// R's t.test: stderrx <- sqrt(vx/nx); stderry <- sqrt(vy/ny); stderr <- sqrt(stderrx^2 + stderry^2);
// df <- stderr^4/(stderrx^4/(nx-1) + stderry^4/(ny-1)) (Welch 1947; Satterthwaite 1946).
double welchStandardError(const SampleSummary& x, const SampleSummary& y) {
  const double sx = std::sqrt(x.variance / static_cast<double>(x.n));
  const double sy = std::sqrt(y.variance / static_cast<double>(y.n));
  return std::sqrt(sx * sx + sy * sy);
}
}  // namespace

double welchSatterthwaiteDf(const SampleSummary& x, const SampleSummary& y) {
  const double sx = std::sqrt(x.variance / static_cast<double>(x.n));
  const double sy = std::sqrt(y.variance / static_cast<double>(y.n));
  const double se = welchStandardError(x, y);
  return std::pow(se, 4.0) /
         (std::pow(sx, 4.0) / static_cast<double>(x.n - 1) + std::pow(sy, 4.0) / static_cast<double>(y.n - 1));
}

TTestResult oneSampleTTestFromSummary(const SampleSummary& x, double mu0, Alternative alternative,
                                      double confidence) {
  requireAtLeastTwo(x, "the sample");
  TTestResult r;
  r.kind = TTestKind::OneSample;
  r.alternative = alternative;
  r.confidence = confidence;
  r.first = x;
  r.meanDiff = x.mean - mu0;
  r.df = static_cast<double>(x.n - 1);
  r.se = std::sqrt(x.variance / static_cast<double>(x.n));
  requireNonzeroStandardError(r.se, r.meanDiff, "all values are equal", std::fabs(x.mean));
  r.cohensD = r.meanDiff / std::sqrt(x.variance);
  finish(r, r.df, mu0);  // R reports the interval of the mean itself
  return r;
}

TTestResult pairedTTestFromDifferences(const SampleSummary& d, Alternative alternative,
                                       double confidence) {
  requireAtLeastTwo(d, "the paired sample");
  TTestResult r;
  r.kind = TTestKind::Paired;
  r.alternative = alternative;
  r.confidence = confidence;
  r.first = d;
  r.meanDiff = d.mean;
  r.df = static_cast<double>(d.n - 1);
  r.se = std::sqrt(d.variance / static_cast<double>(d.n));
  requireNonzeroStandardError(r.se, r.meanDiff, "all paired differences are equal", std::fabs(d.mean));
  r.cohensD = d.mean / std::sqrt(d.variance);  // d_z
  finish(r, r.df);
  return r;
}

namespace {
// What the two independent-samples tests share: the checks and the descriptive part of the result.
TTestResult twoSampleResult(TTestKind kind, const SampleSummary& x, const SampleSummary& y, Alternative alternative,
                            double confidence) {
  requireAtLeastTwo(x, "the first group");
  requireAtLeastTwo(y, "the second group");
  TTestResult r;
  r.kind = kind;
  r.alternative = alternative;
  r.confidence = confidence;
  r.first = x;
  r.second = y;
  r.meanDiff = x.mean - y.mean;
  return r;
}
}  // namespace

TTestResult studentTTestFromSummaries(const SampleSummary& x, const SampleSummary& y,
                                      Alternative alternative, double confidence) {
  TTestResult r = twoSampleResult(TTestKind::Student, x, y, alternative, confidence);
  r.df = static_cast<double>(x.n + y.n - 2);
  const double sp2 = pooledVariance(x, y);
  r.se = std::sqrt(sp2 * (1.0 / static_cast<double>(x.n) + 1.0 / static_cast<double>(y.n)));
  requireNonzeroStandardError(r.se, r.meanDiff, "both groups are constant",
                              std::max(std::fabs(x.mean), std::fabs(y.mean)));
  r.cohensD = r.meanDiff / std::sqrt(sp2);
  finish(r, r.df);
  return r;
}

TTestResult welchTTestFromSummaries(const SampleSummary& x, const SampleSummary& y,
                                    Alternative alternative, double confidence) {
  TTestResult r = twoSampleResult(TTestKind::Welch, x, y, alternative, confidence);
  r.se = welchStandardError(x, y);
  requireNonzeroStandardError(r.se, r.meanDiff, "both groups are constant",
                              std::max(std::fabs(x.mean), std::fabs(y.mean)));
  r.df = welchSatterthwaiteDf(x, y);
  r.cohensD = r.meanDiff / std::sqrt(pooledVariance(x, y));
  finish(r, static_cast<double>(x.n + y.n - 2));
  return r;
}

TTestResult oneSampleTTest(std::span<const double> x, double mu0, Alternative alternative,
                           double confidence) {
  return oneSampleTTestFromSummary(summarizeSample(x, "the sample"), mu0, alternative, confidence);
}

TTestResult pairedTTest(std::span<const double> x, std::span<const double> y, Alternative alternative,
                        double confidence) {
  if (x.size() != y.size())
    throw AnalysisError("paired t-test needs equally many x and y values, got " +
                        std::to_string(x.size()) + " and " + std::to_string(y.size()));
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) d[i] = x[i] - y[i];
  return pairedTTestFromDifferences(summarizeSample(d, "the paired sample"), alternative, confidence);
}

TTestResult studentTTest(std::span<const double> x, std::span<const double> y, Alternative alternative,
                         double confidence) {
  return twoSampleTTest(x, y, alternative, confidence, studentTTestFromSummaries);
}

TTestResult welchTTest(std::span<const double> x, std::span<const double> y, Alternative alternative,
                       double confidence) {
  return twoSampleTTest(x, y, alternative, confidence, welchTTestFromSummaries);
}

}  // namespace tlab::analysis
