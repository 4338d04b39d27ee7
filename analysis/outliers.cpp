#include "analysis/outliers.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/descriptives.hpp"
#include "analysis/r_moments.hpp"

namespace tlab::analysis {

std::string_view outlierRuleName(OutlierRule rule) {
  return rule == OutlierRule::TukeyFences ? "Tukey fences (1.5 IQR)" : "|z| > 3";
}

OutlierScreen screenOutliers(std::span<const double> xs) {
  OutlierScreen screen;
  if (xs.empty()) return screen;
  std::vector<double> sorted(xs.begin(), xs.end());
  std::sort(sorted.begin(), sorted.end());
  const double q1 = quantileType7(sorted, 0.25);
  const double q3 = quantileType7(sorted, 0.75);
  screen.lowerFence = q1 - 1.5 * (q3 - q1);
  screen.upperFence = q3 + 1.5 * (q3 - q1);
  const double mean = rMean(xs);
  const double sd = xs.size() > 1 ? std::sqrt(rVariance(xs)) : 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double z = sd > 0.0 ? (xs[i] - mean) / sd : 0.0;
    if (xs[i] < screen.lowerFence || xs[i] > screen.upperFence)
      screen.outliers.push_back({i, xs[i], z, OutlierRule::TukeyFences});
    if (std::fabs(z) > 3.0) screen.outliers.push_back({i, xs[i], z, OutlierRule::AbsoluteZAbove3});
  }
  return screen;
}

}  // namespace tlab::analysis
