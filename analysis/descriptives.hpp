#pragma once
// Descriptive statistics of one sample (one cell of a design): n, mean, standard deviation,
// variance, standard error, t-based confidence interval of the mean, and the five-number summary
// used by the box plots.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace tlab::analysis {

// The sufficient statistics of the t-tests: size, mean and unbiased variance (divisor n - 1).
struct SampleSummary {
  std::size_t n = 0;
  double mean = 0.0;
  double variance = 0.0;
};

// Two-pass (corrected) mean and variance; `label` names the sample in errors ("group 'ctrl'").
// Throws AnalysisError when n < 2 (no variance can be estimated).
SampleSummary summarizeSample(std::span<const double> xs, const std::string& label);

struct Descriptives {
  std::size_t n = 0;
  double mean = 0.0;
  double sd = 0.0;
  double variance = 0.0;
  double se = 0.0;         // sd / sqrt(n)
  double ciLow = 0.0;      // mean ± t_{n-1}(1 - (1-confidence)/2) · se
  double ciHigh = 0.0;
  double confidence = 0.95;
  double min = 0.0;
  double q1 = 0.0;         // quartiles by R's default quantile definition (type 7)
  double median = 0.0;
  double q3 = 0.0;
  double max = 0.0;
};

Descriptives describe(std::span<const double> xs, const std::string& label, double confidence = 0.95);

// Sample quantile of sorted data, Hyndman & Fan (1996) definition 7 (R's default):
// h = (n-1)p, Q = x[floor h] + (h - floor h)(x[floor h + 1] - x[floor h]).
double quantileType7(std::span<const double> sorted, double probability);

}  // namespace tlab::analysis
