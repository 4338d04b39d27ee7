#pragma once
// Means, variances and covariances computed exactly the way R computes them, so that tlab and R
// agree to the last digits even on data far from zero (offset 1e9, spread 1e-3), where the choice
// of algorithm decides the fourth significant digit of a t statistic.
//
// R's mean.default (src/main/summary.c, real_mean) sums in long double, divides by n, then adds
// the mean of the residuals x - m (also in long double) and rounds once to double. R's var and
// cov (src/library/stats/src/cov.c, cov_complete1/2) take that mean rounded to *double* and sum
// (x - m_x) · (y - m_y) in long double, without a correction term, and divide by n - 1. Two consequences worth knowing:
//   - a t statistic uses mean(x) - mean(y) of two means already rounded to double (ulp 1.2e-7 at
//     1e9), exactly as R does; computing the difference more accurately would disagree with R;
//   - the residual-sum correction of Chan, Golub & LeVeque (1983) is deliberately *not* applied
//     to the variance: R does not apply it.
// See R's ?mean ("the mean is computed ... with a second pass") and ?var.
#include <cmath>
#include <limits>
#include <span>

namespace tlab::analysis {

// R's mean(x): long double sum / n, corrected by the mean of x - m; NaN for no values.
inline double rMean(std::span<const double> xs) {
  if (xs.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto n = static_cast<long double>(xs.size());
  long double s = 0.0L;
  for (const double x : xs) s += x;
  s /= n;
  if (std::isfinite(static_cast<double>(s))) {
    long double t = 0.0L;
    for (const double x : xs) t += (x - s);
    s += t / n;
  }
  return static_cast<double>(s);
}

// Σ (x - m_x)(y - m_y) with R's double means and long double accumulation (cov.c).
// (R keeps the double means in long double variables, so the differences are long double too.)
inline long double rCrossProducts(std::span<const double> xs, std::span<const double> ys) {
  const long double mx = rMean(xs);
  const long double my = rMean(ys);
  long double sum = 0.0L;
  for (std::size_t k = 0; k < xs.size() && k < ys.size(); ++k) sum += (xs[k] - mx) * (ys[k] - my);
  return sum;
}

// R's cov(x, y) for equally long x and y; NaN for fewer than two pairs.
inline double rCovariance(std::span<const double> xs, std::span<const double> ys) {
  if (xs.size() < 2 || xs.size() != ys.size()) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(rCrossProducts(xs, ys) / static_cast<long double>(xs.size() - 1));
}

// R's var(x).
inline double rVariance(std::span<const double> xs) { return rCovariance(xs, xs); }

// Σ (x - mean(x))², the numerator of R's var(x) (0 for no values).
inline double sumOfSquaredDeviations(std::span<const double> xs) {
  return xs.empty() ? 0.0 : static_cast<double>(rCrossProducts(xs, xs));
}

}  // namespace tlab::analysis
