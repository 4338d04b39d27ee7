#include "analysis/rank_tests.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "analysis/analysis_error.hpp"
#include "analysis/ranks.hpp"

namespace tlab::analysis {

namespace {

// Number of subsets of {1..n} with each sum s = 0..n(n+1)/2: the null distribution of V times
// 2^n (every sign pattern equally likely). Counts ≤ 2^n are exact in doubles for n ≤ 53.
std::vector<double> signedRankCounts(std::size_t n) {
  std::vector<double> counts(n * (n + 1) / 2 + 1, 0.0);
  counts[0] = 1.0;
  std::size_t top = 0;
  for (std::size_t i = 1; i <= n; ++i) {
    top += i;
    for (std::size_t s = top; s >= i; --s) counts[s] += counts[s - i];
  }
  return counts;
}

// Number of ways the x sample's ranks can give W = u, u = 0..nx·ny: subsets of size nx of
// {1..N} counted by rank sum (a sum of non-negative terms: no cancellation).
std::vector<double> rankSumCounts(std::size_t nx, std::size_t ny) {
  const std::size_t n = nx + ny;
  const std::size_t maxSum = nx * n;
  std::vector<std::vector<double>> ways(nx + 1, std::vector<double>(maxSum + 1, 0.0));
  ways[0][0] = 1.0;
  for (std::size_t item = 1; item <= n; ++item)
    for (std::size_t j = std::min(item, nx); j >= 1; --j)
      for (std::size_t s = maxSum; s >= item; --s) ways[j][s] += ways[j - 1][s - item];
  const std::size_t offset = nx * (nx + 1) / 2;
  return std::vector<double>(ways[nx].begin() + static_cast<std::ptrdiff_t>(offset),
                             ways[nx].begin() + static_cast<std::ptrdiff_t>(offset + nx * ny + 1));
}

// Σ counts[s] for s ≤ q, and for s ≥ q, each divided by the total.
double lowerTailOf(const std::vector<double>& counts, double q) {
  if (q < 0.0) return 0.0;
  double total = 0.0;
  double tail = 0.0;
  for (std::size_t s = 0; s < counts.size(); ++s) {
    total += counts[s];
    if (static_cast<double>(s) <= q) tail += counts[s];
  }
  return tail / total;
}

double upperTailOf(const std::vector<double>& counts, double q) {
  double total = 0.0;
  double tail = 0.0;
  for (std::size_t s = 0; s < counts.size(); ++s) {
    total += counts[s];
    if (static_cast<double>(s) >= q) tail += counts[s];
  }
  return tail / total;
}

double continuityCorrection(double centred, Alternative alternative, bool enabled) {
  if (!enabled) return 0.0;
  switch (alternative) {
    case Alternative::TwoSided: return centred > 0 ? 0.5 : (centred < 0 ? -0.5 : 0.0);
    case Alternative::Greater: return 0.5;
    case Alternative::Less: return -0.5;
  }
  return 0.0;
}

// R: two.sided = 2·min(P(Z ≤ z), P(Z ≥ z)).
double normalApproximationP(double z, Alternative alternative) {
  switch (alternative) {
    case Alternative::Less: return normalLowerTail(z);
    case Alternative::Greater: return normalUpperTail(z);
    case Alternative::TwoSided: return std::min(1.0, 2.0 * std::min(normalLowerTail(z), normalUpperTail(z)));
  }
  return std::nan("");
}

}  // namespace

double signedRankLowerTail(double q, std::size_t n) { return lowerTailOf(signedRankCounts(n), std::floor(q)); }
double signedRankUpperTail(double q, std::size_t n) { return upperTailOf(signedRankCounts(n), std::ceil(q)); }
double rankSumLowerTail(double q, std::size_t nx, std::size_t ny) {
  return lowerTailOf(rankSumCounts(nx, ny), std::floor(q));
}
double rankSumUpperTail(double q, std::size_t nx, std::size_t ny) {
  return upperTailOf(rankSumCounts(nx, ny), std::ceil(q));
}

FriedmanResult friedmanTest(const Eigen::MatrixXd& y) {
  const auto n = y.rows();
  const auto k = y.cols();
  if (k < 2) throw AnalysisError("the Friedman test needs at least 2 conditions, got " + std::to_string(k));
  if (n < 2) throw AnalysisError("the Friedman test needs at least 2 subjects, got " + std::to_string(n));
  std::vector<double> rankSums(static_cast<std::size_t>(k), 0.0);
  double tieSum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    std::vector<double> row(static_cast<std::size_t>(k));
    for (Eigen::Index j = 0; j < k; ++j) row[static_cast<std::size_t>(j)] = y(i, j);
    const Ranking r = rankWithTies(row);
    for (std::size_t j = 0; j < row.size(); ++j) rankSums[j] += r.ranks[j];
    tieSum += r.tieCorrectionSum();
  }
  const double nd = static_cast<double>(n);
  const double kd = static_cast<double>(k);
  double deviations = 0.0;
  for (const double rj : rankSums) deviations += (rj - nd * (kd + 1.0) / 2.0) * (rj - nd * (kd + 1.0) / 2.0);
  const double denominator = nd * kd * (kd + 1.0) - tieSum / (kd - 1.0);
  if (!(denominator > 0.0))
    throw AnalysisError("every subject has the same value in all conditions: the Friedman statistic is 0/0");
  FriedmanResult result;
  result.chiSquared = 12.0 * deviations / denominator;
  result.df = kd - 1.0;
  result.p = chiSquaredUpperTail(result.chiSquared, result.df);
  result.blocks = static_cast<std::size_t>(n);
  result.treatments = static_cast<std::size_t>(k);
  return result;
}

WilcoxonSignedRankResult wilcoxonSignedRankTest(std::span<const double> x, std::span<const double> y,
                                                double mu, Alternative alternative,
                                                bool continuityCorrectionEnabled) {
  if (!y.empty() && y.size() != x.size())
    throw AnalysisError("the paired Wilcoxon test needs equally many x and y values, got " +
                        std::to_string(x.size()) + " and " + std::to_string(y.size()));
  if (x.empty()) throw AnalysisError("the Wilcoxon signed-rank test needs at least one observation");
  WilcoxonSignedRankResult result;
  result.alternative = alternative;
  std::vector<double> d;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double di = (y.empty() ? x[i] : x[i] - y[i]) - mu;
    if (di == 0.0)
      ++result.zeros;
    else
      d.push_back(di);
  }
  if (d.empty())
    throw AnalysisError("all " + std::to_string(x.size()) +
                        " differences are zero: the Wilcoxon signed-rank test is undefined");
  std::vector<double> magnitudes(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) magnitudes[i] = std::fabs(d[i]);
  const Ranking ranking = rankWithTies(magnitudes);
  for (std::size_t i = 0; i < d.size(); ++i)
    if (d[i] > 0) result.V += ranking.ranks[i];
  result.n = d.size();
  result.ties = ranking.hasTies();
  const double n = static_cast<double>(result.n);
  result.exact = result.n < 50 && !result.ties && result.zeros == 0;
  if (result.exact) {
    const std::vector<double> counts = signedRankCounts(result.n);
    switch (alternative) {
      case Alternative::TwoSided: {
        const double p = result.V > n * (n + 1.0) / 4.0 ? upperTailOf(counts, result.V)
                                                        : lowerTailOf(counts, result.V);
        result.p = std::min(1.0, 2.0 * p);
        break;
      }
      case Alternative::Greater: result.p = upperTailOf(counts, result.V); break;
      case Alternative::Less: result.p = lowerTailOf(counts, result.V); break;
    }
    return result;
  }
  const double centred = result.V - n * (n + 1.0) / 4.0;
  const double sigma = std::sqrt(n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - ranking.tieCorrectionSum() / 48.0);
  result.z = (centred - continuityCorrection(centred, alternative, continuityCorrectionEnabled)) / sigma;
  result.p = normalApproximationP(result.z, alternative);
  return result;
}

MannWhitneyResult mannWhitneyTest(std::span<const double> x, std::span<const double> y,
                                  Alternative alternative, bool continuityCorrectionEnabled) {
  if (x.empty() || y.empty())
    throw AnalysisError("the Mann-Whitney test needs observations in both groups (got " +
                        std::to_string(x.size()) + " and " + std::to_string(y.size()) + ")");
  MannWhitneyResult result;
  result.alternative = alternative;
  result.nx = x.size();
  result.ny = y.size();
  std::vector<double> pooled(x.begin(), x.end());
  pooled.insert(pooled.end(), y.begin(), y.end());
  const Ranking ranking = rankWithTies(pooled);
  double rankSumX = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) rankSumX += ranking.ranks[i];
  const double nx = static_cast<double>(x.size());
  const double ny = static_cast<double>(y.size());
  result.W = rankSumX - nx * (nx + 1.0) / 2.0;
  result.ties = ranking.hasTies();
  result.exact = x.size() < 50 && y.size() < 50 && !result.ties;
  if (result.exact) {
    const std::vector<double> counts = rankSumCounts(x.size(), y.size());
    switch (alternative) {
      case Alternative::TwoSided: {
        const double p = result.W > nx * ny / 2.0 ? upperTailOf(counts, result.W) : lowerTailOf(counts, result.W);
        result.p = std::min(1.0, 2.0 * p);
        break;
      }
      case Alternative::Greater: result.p = upperTailOf(counts, result.W); break;
      case Alternative::Less: result.p = lowerTailOf(counts, result.W); break;
    }
    return result;
  }
  const double centred = result.W - nx * ny / 2.0;
  const double sigma = std::sqrt((nx * ny / 12.0) *
                                 ((nx + ny + 1.0) - ranking.tieCorrectionSum() / ((nx + ny) * (nx + ny - 1.0))));
  if (!(sigma > 0.0))
    throw AnalysisError("all " + std::to_string(pooled.size()) +
                        " values are tied: the Mann-Whitney statistic has zero variance");
  result.z = (centred - continuityCorrection(centred, alternative, continuityCorrectionEnabled)) / sigma;
  result.p = normalApproximationP(result.z, alternative);
  return result;
}

}  // namespace tlab::analysis
