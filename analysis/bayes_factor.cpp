#include "analysis/bayes_factor.hpp"

#include <boost/math/quadrature/sinh_sinh.hpp>
#include <cmath>
#include <numbers>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

// log of the integrand of Rouder et al. (2009) Eq. 1 (numerator) at g = e^u, times the Jacobian
// dg = e^u du, minus the log of the null likelihood (1 + t²/ν)^{-(ν+1)/2}.
double logIntegrand(double u, double t, double n, double nu, double r) {
  const double g = std::exp(u);
  const double a = 1.0 + n * g * r * r;
  return -0.5 * std::log(a) - 0.5 * (nu + 1.0) * std::log1p(t * t / (a * nu)) - 0.5 * std::log(2.0 * std::numbers::pi) -
         1.5 * u - 0.5 / g + u + 0.5 * (nu + 1.0) * std::log1p(t * t / nu);
}

}  // namespace

double jzsLogBayesFactor10(double t, double effectiveN, double df, double rscale) {
  if (!(effectiveN > 0.0) || !(df > 0.0) || !(rscale > 0.0) || !std::isfinite(t))
    throw AnalysisError("the Bayes factor needs a finite t, n > 0, df > 0 and --rscale > 0");
  // The integrand over u = log g is smooth and unimodal; scale it by its maximum (found on a grid
  // refined around the best point) so that large |t| neither overflows nor loses the peak.
  double best = -60.0, bestValue = logIntegrand(best, t, effectiveN, df, rscale);
  const auto search = [&](double centre, double step, int half) {
    for (int k = -half; k <= half; ++k) {
      const double u = centre + k * step;
      const double v = logIntegrand(u, t, effectiveN, df, rscale);
      if (v > bestValue) bestValue = v, best = u;
    }
  };
  search(0.0, 0.5, 120);  // u in [-60, 60]
  search(best, 0.05, 10);
  search(best, 0.005, 10);
  const auto f = [&](double s) {
    const double v = logIntegrand(best + s, t, effectiveN, df, rscale) - bestValue;
    return v < -745.0 ? 0.0 : std::exp(v);
  };
  boost::math::quadrature::sinh_sinh<double> integrator;
  const double integral = integrator.integrate(f, 1e-13);
  return bestValue + std::log(integral);
}

double jzsBayesFactor10(const TTestResult& test, double rscale) {
  if (test.alternative != Alternative::TwoSided)
    throw AnalysisError("the Bayes factor is computed for the two-sided alternative only");
  switch (test.kind) {
    case TTestKind::OneSample:
    case TTestKind::Paired: {
      const double n = static_cast<double>(test.first.n);
      return std::exp(jzsLogBayesFactor10(test.t, n, n - 1.0, rscale));
    }
    case TTestKind::Student:
    case TTestKind::Welch: {
      const TTestResult student = studentTTestFromSummaries(test.first, test.second, Alternative::TwoSided);
      const double n1 = static_cast<double>(test.first.n), n2 = static_cast<double>(test.second.n);
      return std::exp(jzsLogBayesFactor10(student.t, n1 * n2 / (n1 + n2), n1 + n2 - 2.0, rscale));
    }
  }
  return std::nan("");
}

}  // namespace tlab::analysis
