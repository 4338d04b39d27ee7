#include "analysis/penalized_least_squares.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Cholesky = Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>>;

// A = (ZΛ)ᵀ W (ZΛ) + I (the upper-left block of Eq. 17), factored as in Eq. 18.
void factor(Cholesky& chol, const SparseMatrix& zl, const Eigen::VectorXd* weights) {
  SparseMatrix identity(zl.cols(), zl.cols());
  identity.setIdentity();
  const SparseMatrix a = weights ? SparseMatrix(zl.transpose() * weights->asDiagonal() * zl) + identity
                                 : SparseMatrix(zl.transpose() * zl) + identity;
  chol.compute(a);
  if (chol.info() != Eigen::Success) throw AnalysisError("mixed model: the Cholesky factor of ΛᵀZᵀZΛ + I failed");
}

double logDeterminant2(const Cholesky& chol) {
  const SparseMatrix l = chol.matrixL();
  double s = 0.0;
  for (Eigen::Index j = 0; j < l.cols(); ++j) s += std::log(l.coeff(j, j));
  return 2.0 * s;
}

// Binomial deviance residual with the logit link, from η directly (no 1 - μ cancellation):
// d = −2[y log μ + (1 − y) log(1 − μ)], log μ = −log(1 + e^{−η}), log(1 − μ) = −log(1 + e^{η}).
double log1pExp(double x) { return x > 0 ? x + std::log1p(std::exp(-x)) : std::log1p(std::exp(x)); }
double devianceResidual(double y, double eta) { return 2.0 * (y * log1pExp(-eta) + (1.0 - y) * log1pExp(eta)); }

}  // namespace

Eigen::MatrixXd blockFactor(const RandomEffectsBlock& block, const Eigen::VectorXd& theta) {
  const auto p = static_cast<Eigen::Index>(block.size());
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(p, p);
  Eigen::Index k = static_cast<Eigen::Index>(block.thetaOffset);
  for (Eigen::Index j = 0; j < p; ++j)
    for (Eigen::Index i = j; i < p; ++i) t(i, j) = theta(k++);
  return t;
}

SparseMatrix relativeCovarianceFactor(const MixedModelMatrices& m, const Eigen::VectorXd& theta) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& b : m.blocks) {
    const Eigen::MatrixXd t = blockFactor(b, theta);
    const auto p = static_cast<int>(b.size());
    for (std::size_t level = 0; level < b.levels; ++level) {
      const int base = static_cast<int>(b.offset + level * b.size());
      for (int j = 0; j < p; ++j)
        for (int i = j; i < p; ++i) triplets.emplace_back(base + i, base + j, t(i, j));
    }
  }
  SparseMatrix lambda(m.Z.cols(), m.Z.cols());
  lambda.setFromTriplets(triplets.begin(), triplets.end());
  return lambda;
}

Eigen::VectorXd thetaLowerBounds(const MixedModelMatrices& m) {
  Eigen::VectorXd lower(static_cast<Eigen::Index>(m.thetaSize()));
  for (const auto& b : m.blocks) {
    Eigen::Index k = static_cast<Eigen::Index>(b.thetaOffset);
    for (std::size_t j = 0; j < b.size(); ++j)
      for (std::size_t i = j; i < b.size(); ++i) lower(k++) = i == j ? 0.0 : -std::numeric_limits<double>::infinity();
  }
  return lower;
}

Eigen::VectorXd thetaStart(const MixedModelMatrices& m) {
  Eigen::VectorXd start(static_cast<Eigen::Index>(m.thetaSize()));
  for (const auto& b : m.blocks) {
    Eigen::Index k = static_cast<Eigen::Index>(b.thetaOffset);
    for (std::size_t j = 0; j < b.size(); ++j)
      for (std::size_t i = j; i < b.size(); ++i) start(k++) = i == j ? 1.0 : 0.0;
  }
  return start;
}

PlsSolution solveLinearMixedModel(const MixedModelMatrices& m, const Eigen::VectorXd& theta) {
  const SparseMatrix zl = m.Z * relativeCovarianceFactor(m, theta);
  Cholesky chol;
  factor(chol, zl, nullptr);
  PlsSolution s;
  s.logDetL2 = logDeterminant2(chol);
  const Eigen::MatrixXd zlx = zl.transpose() * m.X;           // ΛᵀZᵀX
  const Eigen::VectorXd zly = zl.transpose() * m.y;           // ΛᵀZᵀy
  const Eigen::MatrixXd ainvZlx = chol.solve(zlx);            // A⁻¹ΛᵀZᵀX, so R_ZXᵀR_ZX = (ΛᵀZᵀX)ᵀ A⁻¹ΛᵀZᵀX (Eq. 49)
  const Eigen::VectorXd ainvZly = chol.solve(zly);            // A⁻¹ΛᵀZᵀy, so R_ZXᵀc_u = (ΛᵀZᵀX)ᵀ A⁻¹ΛᵀZᵀy (Eq. 48)
  s.RXtRX = m.X.transpose() * m.X - zlx.transpose() * ainvZlx;  // Eq. 50
  const Eigen::LLT<Eigen::MatrixXd> rx(s.RXtRX);
  if (rx.info() != Eigen::Success) throw AnalysisError("mixed model: R_XᵀR_X is not positive definite");
  s.logDetRX2 = 2.0 * rx.matrixLLT().diagonal().array().log().sum();
  s.beta = rx.solve(m.X.transpose() * m.y - zlx.transpose() * ainvZly);  // Eq. 51
  s.u = ainvZly - ainvZlx * s.beta;                                       // Eq. 52
  s.pwrss = (m.y - m.X * s.beta - zl * s.u).squaredNorm() + s.u.squaredNorm();  // Eq. 14
  return s;
}

double profiledDeviance(const PlsSolution& s, std::size_t n, std::size_t p, bool reml) {
  const double nd = static_cast<double>(n), pd = static_cast<double>(p);
  const double twoPi = 2.0 * std::numbers::pi;
  if (!reml) return s.logDetL2 + nd * (1.0 + std::log(twoPi * s.pwrss / nd));                  // Eq. 34
  return s.logDetL2 + s.logDetRX2 + (nd - pd) * (1.0 + std::log(twoPi * s.pwrss / (nd - pd)));  // Eq. 41
}

double devianceAtSigma(const PlsSolution& s, std::size_t n, std::size_t p, bool reml, double sigma) {
  const double sigma2 = sigma * sigma, twoPi = 2.0 * std::numbers::pi;
  const double ml = s.logDetL2 + s.pwrss / sigma2 + static_cast<double>(n) * std::log(twoPi * sigma2);  // Eq. 31
  if (!reml) return ml;
  return ml + s.logDetRX2 - static_cast<double>(p) * std::log(twoPi * sigma2);                       // Eq. 39
}

LaplaceSolution laplaceDeviance(const MixedModelMatrices& m, const Eigen::VectorXd& theta, const Eigen::VectorXd& beta,
                                const Eigen::VectorXd* start) {
  const SparseMatrix zl = m.Z * relativeCovarianceFactor(m, theta);
  const Eigen::VectorXd offset = m.X * beta;
  const auto n = m.y.size();
  const auto objective = [&](const Eigen::VectorXd& u, double& devres) {
    const Eigen::VectorXd eta = offset + zl * u;
    devres = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) devres += devianceResidual(m.y(i), eta(i));
    return devres + u.squaredNorm();
  };
  LaplaceSolution s;
  s.u = start && start->size() == zl.cols() ? *start : Eigen::VectorXd::Zero(zl.cols());
  double current = objective(s.u, s.devianceResiduals);
  Cholesky chol;
  Eigen::VectorXd w(n), mu(n);
  const auto weigh = [&](const Eigen::VectorXd& u) {
    const Eigen::VectorXd eta = offset + zl * u;
    for (Eigen::Index i = 0; i < n; ++i) mu(i) = 1.0 / (1.0 + std::exp(-eta(i))), w(i) = mu(i) * (1.0 - mu(i));
  };
  // PIRLS: Newton steps δ = A⁻¹(ΛᵀZᵀ(y − μ) − u) on Σ d_i + ‖u‖², halved until the objective drops.
  // Near the mode the predicted decrease δᵀ(ΛᵀZᵀ(y − μ) − u) falls below rounding; the last Newton
  // step is then taken unchecked (its error is O(‖δ‖²)), so ũ is exact to rounding: the Laplace
  // deviance depends on ũ through log|L|² at first order.
  bool done = false;
  for (int iteration = 0; iteration < 100 && !done; ++iteration) {
    weigh(s.u);
    factor(chol, zl, &w);
    const Eigen::VectorXd rhs = zl.transpose() * (m.y - mu) - s.u;
    const Eigen::VectorXd delta = chol.solve(rhs);
    if (delta.dot(rhs) < 1e-15 * (std::fabs(current) + 1.0)) {
      s.u += delta;
      done = true;
      break;
    }
    double step = 1.0, next = 0.0, devres = 0.0;
    for (int halving = 0; halving < 20; ++halving, step /= 2.0) {
      next = objective(s.u + step * delta, devres);
      if (next < current) break;
    }
    if (!(next < current)) {  // no step decreases the objective: at the mode to rounding, take the Newton step
      s.u += delta;
      done = true;
      break;
    }
    s.u += step * delta;
    current = next;
  }
  s.converged = done;
  current = objective(s.u, s.devianceResiduals);
  weigh(s.u);
  factor(chol, zl, &w);
  s.deviance = current + logDeterminant2(chol);
  return s;
}

}  // namespace tlab::analysis
