#pragma once
// t-tests: one-sample, paired, Student (pooled variance) and Welch (Welch-Satterthwaite df), each
// with the three alternatives, the estimate (mean difference), its confidence interval and
// standardized effect sizes. Formulas follow R's stats::t.test; effect sizes follow Cohen (1988)
// and Hedges (1981).
#include <span>
#include <string>
#include <string_view>

#include "analysis/descriptives.hpp"
#include "analysis/distributions.hpp"

namespace tlab::analysis {

enum class TTestKind { OneSample, Paired, Student, Welch };
std::string_view tTestKindName(TTestKind kind);  // "one-sample", "paired", "student", "welch"

struct TTestResult {
  TTestKind kind = TTestKind::Welch;
  Alternative alternative = Alternative::TwoSided;
  double confidence = 0.95;
  double t = 0.0;
  double df = 0.0;
  double p = 1.0;
  double meanDiff = 0.0;  // x̄ - μ0 (one-sample), mean of x - y (paired), x̄ - ȳ (two-sample)
  double se = 0.0;        // standard error of meanDiff
  // Confidence interval of the estimate as R's t.test reports it: of the mean x̄ (one-sample,
  // i.e. meanDiff + μ0), of the mean difference (paired), of x̄ - ȳ (two-sample). One-sided
  // alternatives give a one-sided interval with an infinite end.
  double ciLow = 0.0;
  double ciHigh = 0.0;
  // Cohen's d: (x̄ - μ0)/s (one-sample); d_z = d̄/s_d (paired, Cohen 1988 Eq. 2.3.5);
  // (x̄ - ȳ)/s_pooled for Student and Welch alike (s_pooled² = ((n1-1)s1² + (n2-1)s2²)/(n1+n2-2)).
  double cohensD = 0.0;
  // Hedges' g = J(m)·d with the exact small-sample factor J(m) = Γ(m/2) / (√(m/2) Γ((m-1)/2))
  // (Hedges 1981, Eq. 6e), m = n - 1 (one-sample, paired) or n1 + n2 - 2 (two-sample).
  double hedgesG = 0.0;
  SampleSummary first;   // x (or the differences, for paired)
  SampleSummary second;  // y (two-sample tests only)
};

// The data versions subtract a reference value (μ0, or the first observation for two samples)
// before averaging, so that x̄ - μ0 and x̄ - ȳ keep their digits when the data sit far from zero
// (e.g. 1e9 + 1e-3·k): a mean stored as a double near 1e9 is only known to ±6e-8.
// One-sample t = (x̄ - μ0)/(s/√n), df = n - 1.
TTestResult oneSampleTTest(std::span<const double> x, double mu0, Alternative alternative,
                           double confidence = 0.95);
// Paired: the one-sample test on d = x - y (x and y aligned by subject).
TTestResult pairedTTest(std::span<const double> x, std::span<const double> y, Alternative alternative,
                        double confidence = 0.95);
// Student: t = (x̄ - ȳ)/(s_p √(1/n1 + 1/n2)), df = n1 + n2 - 2.
TTestResult studentTTest(std::span<const double> x, std::span<const double> y, Alternative alternative,
                         double confidence = 0.95);
// Welch (1947): t = (x̄ - ȳ)/√(s1²/n1 + s2²/n2),
// df = (s1²/n1 + s2²/n2)² / ((s1²/n1)²/(n1-1) + (s2²/n2)²/(n2-1))  (Satterthwaite 1946).
TTestResult welchTTest(std::span<const double> x, std::span<const double> y, Alternative alternative,
                       double confidence = 0.95);

// The same tests from published summary statistics (used to reproduce the seeds' tables).
TTestResult oneSampleTTestFromSummary(const SampleSummary& x, double mu0, Alternative alternative,
                                      double confidence = 0.95);
TTestResult pairedTTestFromDifferences(const SampleSummary& differences, Alternative alternative,
                                       double confidence = 0.95);
TTestResult studentTTestFromSummaries(const SampleSummary& x, const SampleSummary& y,
                                      Alternative alternative, double confidence = 0.95);
TTestResult welchTTestFromSummaries(const SampleSummary& x, const SampleSummary& y,
                                    Alternative alternative, double confidence = 0.95);

// Welch-Satterthwaite degrees of freedom alone (Satterthwaite 1946, Eq. 17 with two terms).
double welchSatterthwaiteDf(const SampleSummary& x, const SampleSummary& y);
// Hedges' exact bias-correction factor J(m) (computed in log space: Γ overflows for m > 340).
double hedgesCorrection(double m);

}  // namespace tlab::analysis
