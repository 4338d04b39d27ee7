#include "analysis/descriptives.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/analysis_error.hpp"
#include "analysis/distributions.hpp"
#include "analysis/stable_sum.hpp"

namespace tlab::analysis {

SampleSummary summarizeSample(std::span<const double> xs, const std::string& label) {
  if (xs.size() < 2)
    throw AnalysisError(label + " has n = " + std::to_string(xs.size()) +
                        "; at least 2 observations are needed to estimate a variance");
  SampleSummary s;
  s.n = xs.size();
  s.mean = stableMean(xs);
  s.variance = sumOfSquaredDeviations(xs) / static_cast<double>(s.n - 1);
  return s;
}

double quantileType7(std::span<const double> sorted, double probability) {
  if (sorted.empty()) return std::nan("");
  const double h = (static_cast<double>(sorted.size()) - 1.0) * probability;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - std::floor(h)) * (sorted[hi] - sorted[lo]);
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
