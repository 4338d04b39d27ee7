#pragma once
// NeumaierSum: compensated summation (Neumaier 1974, "Rundungsfehleranalyse einiger Verfahren zur
// Summation endlicher Summen", ZAMM 54; an improvement of Kahan 1965 that also handles terms larger
// than the running sum). The error of the total is O(eps) independent of the number of terms, which
// together with two-pass centring keeps means and sums of squares accurate for data such as
// 1e9 + 1e-3·k.
#include <cmath>
#include <span>

namespace tlab::analysis {

class NeumaierSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    if (std::fabs(sum_) >= std::fabs(x))
      compensation_ += (sum_ - t) + x;
    else
      compensation_ += (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

inline double stableSum(std::span<const double> xs) {
  NeumaierSum s;
  for (const double x : xs) s.add(x);
  return s.value();
}

// Arithmetic mean by compensated summation, refined by one correction pass: the mean of the
// residuals x - m is added back (the "corrected two-pass" idea of Chan, Golub & LeVeque 1983,
// Am. Stat. 37(3) 242-247), so the result is the correctly rounded mean in all but pathological cases.
inline double stableMean(std::span<const double> xs) {
  if (xs.empty()) return std::nan("");
  const double n = static_cast<double>(xs.size());
  const double m = stableSum(xs) / n;
  NeumaierSum r;
  for (const double x : xs) r.add(x - m);
  return m + r.value() / n;
}

// Sum of squared deviations from the mean, Σ(x - x̄)², by the corrected two-pass algorithm
// (Chan, Golub & LeVeque 1983, Eq. 1.7): Σ(x-m)² - (Σ(x-m))²/n. Never the one-pass
// Σx² - (Σx)²/n, which cancels catastrophically for data far from zero.
inline double sumOfSquaredDeviations(std::span<const double> xs) {
  if (xs.empty()) return 0.0;
  const double m = stableMean(xs);
  NeumaierSum squares;
  NeumaierSum residuals;
  for (const double x : xs) {
    const double d = x - m;
    squares.add(d * d);
    residuals.add(d);
  }
  const double r = residuals.value();
  return squares.value() - r * r / static_cast<double>(xs.size());
}

}  // namespace tlab::analysis
