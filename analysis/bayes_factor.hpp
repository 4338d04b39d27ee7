#pragma once
// The JZS Bayes factor of a t-test (Rouder, Speckman, Sun, Morey & Iverson 2009, "Bayesian t tests
// for accepting and rejecting the null hypothesis", Psychon. Bull. Rev. 16: Eq. 1 with a Cauchy
// prior of scale r on the standardized effect δ), as BayesFactor::ttestBF computes it:
//   BF10 = ∫₀^∞ (1 + N g r²)^{-1/2} (1 + t²/((1 + N g r²) ν))^{-(ν+1)/2} (2π)^{-1/2} g^{-3/2} e^{-1/(2g)} dg
//          / (1 + t²/ν)^{-(ν+1)/2}
// with N = n, ν = n - 1 (one-sample and paired: t of the one-sample test on the differences) or
// N = n1 n2/(n1 + n2), ν = n1 + n2 - 2 and Student's pooled-variance t (two samples).
#include "analysis/ttest.hpp"

namespace tlab::analysis {

// BayesFactor's "medium" scale √2/2.
inline constexpr double kMediumCauchyScale = 0.70710678118654752440;

// log BF10 of an observed t with effective sample size N and ν degrees of freedom.
double jzsLogBayesFactor10(double t, double effectiveN, double df, double rscale);

// BF10 of a two-sided t-test result (one-sample, paired, Student or Welch: for two samples the
// Student t of the same data is used, as ttestBF does). Throws AnalysisError for one-sided tests.
double jzsBayesFactor10(const TTestResult& test, double rscale);

}  // namespace tlab::analysis
