#include "analysis/numerical_derivatives.hpp"

#include <cmath>

namespace tlab::analysis {

namespace {

double step(double x, const DerivativeSteps& s) { return std::fabs(x) < s.zeroTolerance ? s.absolute : s.relative * std::fabs(x); }

// Richardson extrapolation of estimates a[k] taken with steps h/2^k, error O(h²) each:
// a ← (4^m a[k+1] − a[k]) / (4^m − 1), m = 1..r−1 (numDeriv's scheme with v = 2).
template <class T>
T extrapolate(std::vector<T> a) {
  const int levels = static_cast<int>(a.size());
  for (int m = 1; m < levels; ++m) {
    const double f = std::pow(4.0, m);
    for (std::size_t k = 0; k + 1 < a.size(); ++k) a[k] = (f * a[k + 1] - a[k]) / (f - 1.0);
    a.pop_back();
  }
  return a.front();
}

Eigen::VectorXd shifted(const Eigen::VectorXd& x, Eigen::Index i, double hi) {
  Eigen::VectorXd y = x;
  y(i) += hi;
  return y;
}

}  // namespace

Eigen::VectorXd richardsonGradient(const ScalarFunction& f, const Eigen::VectorXd& x, const DerivativeSteps& steps) {
  Eigen::VectorXd g(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    std::vector<double> a;
    for (int k = 0; k < steps.levels; ++k) {
      const double h = step(x(i), steps) / std::pow(2.0, k);
      a.push_back((f(shifted(x, i, h)) - f(shifted(x, i, -h))) / (2.0 * h));
    }
    g(i) = extrapolate(a);
  }
  return g;
}

Eigen::MatrixXd richardsonHessian(const ScalarFunction& f, const Eigen::VectorXd& x, const DerivativeSteps& steps) {
  const Eigen::Index n = x.size();
  Eigen::MatrixXd h(n, n);
  const double f0 = f(x);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j <= i; ++j) {
      std::vector<double> a;
      for (int k = 0; k < steps.levels; ++k) {
        const double hi = step(x(i), steps) / std::pow(2.0, k), hj = step(x(j), steps) / std::pow(2.0, k);
        if (i == j) {
          a.push_back((f(shifted(x, i, hi)) - 2.0 * f0 + f(shifted(x, i, -hi))) / (hi * hi));
        } else {
          const auto at = [&](double si, double sj) { return f(shifted(shifted(x, i, si * hi), j, sj * hj)); };
          a.push_back((at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4.0 * hi * hj));
        }
      }
      h(i, j) = h(j, i) = extrapolate(a);
    }
  return h;
}

std::vector<Eigen::MatrixXd> richardsonJacobian(const MatrixFunction& f, const Eigen::VectorXd& x, const DerivativeSteps& steps) {
  std::vector<Eigen::MatrixXd> out;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    std::vector<Eigen::MatrixXd> a;
    for (int k = 0; k < steps.levels; ++k) {
      const double h = step(x(i), steps) / std::pow(2.0, k);
      a.push_back((f(shifted(x, i, h)) - f(shifted(x, i, -h))) / (2.0 * h));
    }
    out.push_back(extrapolate(a));
  }
  return out;
}

}  // namespace tlab::analysis
