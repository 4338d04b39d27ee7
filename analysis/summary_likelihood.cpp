#include "analysis/summary_likelihood.hpp"

#include <cmath>
#include <limits>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

double summaryLogLikelihood(std::size_t n, double m, double v, double mu, double sigma2) {
  if (n < 2) throw AnalysisError("a published summary needs n >= 2, got " + std::to_string(n));
  if (!(sigma2 > 0.0)) return -std::numeric_limits<double>::infinity();
  const double nd = static_cast<double>(n);
  const double k = nd - 1.0;
  constexpr double kLog2Pi = 1.8378770664093454836;
  // log N(m; mu, sigma2/n)
  const double logMean = -0.5 * (kLog2Pi + std::log(sigma2 / nd)) - nd * (m - mu) * (m - mu) / (2.0 * sigma2);
  if (!(v > 0.0)) return logMean;  // a variance of 0 says nothing more (and has density 0 for k >= 1)
  // log of the density of v = sigma2 x / k, x ~ chi2(k): log chi2_k(x) + log(k / sigma2)
  const double x = k * v / sigma2;
  const double logChi2 = (k / 2.0 - 1.0) * std::log(x) - x / 2.0 - (k / 2.0) * std::log(2.0) - std::lgamma(k / 2.0);
  return logMean + logChi2 + std::log(k / sigma2);
}

}  // namespace tlab::analysis
