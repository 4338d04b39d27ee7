#pragma once
// The inner problems of a mixed-model fit for a given covariance parameter θ, in the notation of
// Bates, Mächler, Bolker & Walker (2015), "Fitting linear mixed-effects models using lme4",
// JSS 67(1) (equation numbers refer to it):
// - relativeCovarianceFactor: Λθ (Eq. 4, Σθ = σ² Λθ Λθᵀ), block diagonal with one lower-triangular
//   T_k per level of each grouping factor, θ = the lower triangles of the T_k column by column;
// - solveLinearMixedModel: the penalized least squares problem (Eqs. 14, 16-18) through the
//   normal equations (Eq. 17): A = ΛᵀZᵀZΛ + I = P L Lᵀ Pᵀ (sparse Cholesky, Eq. 18), then
//   c_u, R_ZX, R_X, β̂ and ũ (Eqs. 48-52) — written with full solves against A, i.e.
//   R_ZXᵀR_ZX = (ΛᵀZᵀX)ᵀ A⁻¹ (ΛᵀZᵀX) — and r²(θ) = ‖y − Xβ̂ − ZΛũ‖² + ‖ũ‖² (Eq. 14);
//   the profiled deviance (Eq. 34, ML) or REML criterion (Eq. 41);
// - laplaceDeviance: the binomial GLMM with the logit link for given θ and β: penalized
//   iteratively reweighted least squares for the conditional mode ũ (Section 5 of the lme4
//   "Theory" vignette; Bates 2014, "Computational methods for mixed models", Eqs. 26-29), then the
//   Laplace approximation  −2 log L ≈ Σ d_i(y, μ) + ‖ũ‖² + log|L|²  (lme4's glmer, nAGQ = 1).
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "analysis/model_matrix.hpp"

namespace tlab::analysis {

Eigen::SparseMatrix<double> relativeCovarianceFactor(const MixedModelMatrices& m, const Eigen::VectorXd& theta);
// T_k of one block (p_k × p_k, lower triangular).
Eigen::MatrixXd blockFactor(const RandomEffectsBlock& block, const Eigen::VectorXd& theta);
// Lower bounds of θ: 0 on the diagonals of the T_k, −∞ off them (lme4's lower).
Eigen::VectorXd thetaLowerBounds(const MixedModelMatrices& m);
// lme4's starting value: T_k = I.
Eigen::VectorXd thetaStart(const MixedModelMatrices& m);

struct PlsSolution {
  double logDetL2 = 0.0;    // log|L_θ|²
  double logDetRX2 = 0.0;   // log|R_X|²
  double pwrss = 0.0;       // r²(θ)
  Eigen::VectorXd beta;     // β̂_θ (Eq. 51)
  Eigen::VectorXd u;        // ũ (Eq. 52)
  Eigen::MatrixXd RXtRX;    // R_XᵀR_X (Eq. 50); Var(β̂) = σ² (R_XᵀR_X)⁻¹ (Eq. 54)
};

PlsSolution solveLinearMixedModel(const MixedModelMatrices& m, const Eigen::VectorXd& theta);
// Eq. 34 (ML) or Eq. 41 (REML) at the solution.
double profiledDeviance(const PlsSolution& s, std::size_t n, std::size_t p, bool reml);
// lmerTest's deviance in the variance parameters (θ, σ), not profiled over σ (Eqs. 31 and 39).
double devianceAtSigma(const PlsSolution& s, std::size_t n, std::size_t p, bool reml, double sigma);

struct LaplaceSolution {
  double deviance = 0.0;       // Σ d_i + ‖ũ‖² + log|L|²
  double devianceResiduals = 0.0;
  Eigen::VectorXd u;
  bool converged = true;
};

// PIRLS starts at `start` (the mode of a nearby evaluation, as lme4 keeps u) or at u = 0; the
// objective is convex in u, so either converges to the same mode (to rounding).
LaplaceSolution laplaceDeviance(const MixedModelMatrices& m, const Eigen::VectorXd& theta, const Eigen::VectorXd& beta,
                                const Eigen::VectorXd* start = nullptr);

}  // namespace tlab::analysis
