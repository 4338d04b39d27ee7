#pragma once
// Rank tests with R's conventions (stats::friedman.test, stats::wilcox.test):
//  - Friedman rank sum test, χ² form with the tie correction (Hollander & Wolfe 1999, Eq. 7.8):
//      χ²_F = 12 Σ_j (R_j - n(k+1)/2)² / (n k (k+1) - Σ(t³ - t)/(k - 1)),  df = k - 1.
//  - Wilcoxon signed-rank test on d = x - y - μ: zeros dropped; V = sum of the ranks of |d| for
//    the positive d. Exact null distribution when n < 50 and there are neither ties nor zeros;
//    otherwise the normal approximation z = (V - n(n+1)/4 - c)/σ with
//      σ² = n(n+1)(2n+1)/24 - Σ(t³ - t)/48 and continuity correction c = ±0.5.
//  - Wilcoxon-Mann-Whitney rank sum test: W = R_x - n_x(n_x+1)/2 (R_x: rank sum of x in the
//    pooled sample), i.e. the number of pairs with x > y (ties count 1/2). Exact when n_x < 50,
//    n_y < 50 and no ties; otherwise z = (W - n_x n_y/2 - c)/σ with
//      σ² = (n_x n_y/12)((n_x + n_y + 1) - Σ(t³ - t)/((n_x + n_y)(n_x + n_y - 1))).
// Exact tails are sums of non-negative counts taken on the requested side (never 1 - cdf), so
// tiny p-values keep full relative precision.
#include <Eigen/Dense>
#include <cstddef>
#include <span>

#include "analysis/distributions.hpp"

namespace tlab::analysis {

struct FriedmanResult {
  double chiSquared = 0.0;
  double df = 0.0;
  double p = 1.0;
  std::size_t blocks = 0;      // subjects
  std::size_t treatments = 0;  // conditions
};
// y: one row per subject (block), one column per condition (treatment).
FriedmanResult friedmanTest(const Eigen::MatrixXd& y);

struct WilcoxonSignedRankResult {
  double V = 0.0;
  double p = 1.0;
  bool exact = false;
  std::size_t n = 0;      // non-zero differences used
  std::size_t zeros = 0;  // zero differences dropped
  bool ties = false;
  double z = 0.0;         // normal approximation only
  Alternative alternative = Alternative::TwoSided;
};
// Paired test of x against y (pass an empty y for the one-sample test of x against mu).
WilcoxonSignedRankResult wilcoxonSignedRankTest(std::span<const double> x, std::span<const double> y,
                                                double mu, Alternative alternative,
                                                bool continuityCorrection = true);

struct MannWhitneyResult {
  double W = 0.0;
  double p = 1.0;
  bool exact = false;
  bool ties = false;
  double z = 0.0;
  std::size_t nx = 0;
  std::size_t ny = 0;
  Alternative alternative = Alternative::TwoSided;
};
MannWhitneyResult mannWhitneyTest(std::span<const double> x, std::span<const double> y,
                                  Alternative alternative, bool continuityCorrection = true);

// Exact null distributions, as probabilities P(statistic ≤ q) and P(statistic ≥ q), R's
// psignrank / pwilcox (the ≥ form is R's p*(q - 1, lower.tail = FALSE)).
double signedRankLowerTail(double q, std::size_t n);
double signedRankUpperTail(double q, std::size_t n);
double rankSumLowerTail(double q, std::size_t nx, std::size_t ny);
double rankSumUpperTail(double q, std::size_t nx, std::size_t ny);

}  // namespace tlab::analysis
