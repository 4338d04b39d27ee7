#include "analysis/descriptives.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/analysis_error.hpp"
#include "analysis/distributions.hpp"
#include "analysis/r_moments.hpp"

namespace tlab::analysis {

SampleSummary summarizeSample(std::span<const double> xs, const std::string& label) {
  if (xs.size() < 2)
    throw AnalysisError(label + " has n = " + std::to_string(xs.size()) +
                        "; at least 2 observations are needed to estimate a variance");
  SampleSummary s;
  s.n = xs.size();
  s.mean = rMean(xs);
  s.variance = rVariance(xs);
  return s;
}

// As R's quantile.default computes type 7: index = 1 + (n-1)p, lo = floor(index), and where
// index > lo and x[hi] != x[lo], (1 - h)·x[lo] + h·x[hi] with h = index - lo.
double quantileType7(std::span<const double> sorted, double probability) {
  if (sorted.empty()) return std::nan("");
  const double index = 1.0 + (static_cast<double>(sorted.size()) - 1.0) * probability;
  const double lo = std::floor(index);
  const double hi = std::ceil(index);
  const double xLo = sorted[static_cast<std::size_t>(lo) - 1];
  const double xHi = sorted[std::min(static_cast<std::size_t>(hi), sorted.size()) - 1];
  if (!(index > lo) || xHi == xLo) return xLo;
  const double h = index - lo;
  return (1.0 - h) * xLo + h * xHi;
}

Descriptives describe(std::span<const double> xs, const std::string& label, double confidence) {
  const SampleSummary s = summarizeSample(xs, label);
  Descriptives d;
  d.n = s.n;
  d.mean = s.mean;
  d.variance = s.variance;
  d.sd = std::sqrt(s.variance);
  d.se = d.sd / std::sqrt(static_cast<double>(s.n));
  d.confidence = confidence;
  const double tCrit = studentTQuantile(1.0 - (1.0 - confidence) / 2.0, static_cast<double>(s.n - 1));
  d.ciLow = d.mean - tCrit * d.se;
  d.ciHigh = d.mean + tCrit * d.se;
  std::vector<double> sorted(xs.begin(), xs.end());
  std::sort(sorted.begin(), sorted.end());
  d.min = sorted.front();
  d.max = sorted.back();
  d.q1 = quantileType7(sorted, 0.25);
  d.median = quantileType7(sorted, 0.5);
  d.q3 = quantileType7(sorted, 0.75);
  return d;
}

}  // namespace tlab::analysis
