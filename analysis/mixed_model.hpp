#pragma once
// MixedModel: linear and generalized linear mixed models as lme4 fits them (Bates, Mächler,
// Bolker & Walker 2015, JSS 67(1)) — `tlab stats mixed` and `tests = ["mixed"]` of a study.
// - Gaussian (lmer): θ minimises the profiled REML criterion (Eq. 41) or deviance (Eq. 34) by
//   BOBYQA (bobyqa.hpp); β̂, σ̂² (Eq. 40 or 33) and Var(β̂) = σ̂² (R_XᵀR_X)⁻¹ (Eq. 54) at θ̂.
//   The t-tests of the fixed effects use Satterthwaite's degrees of freedom as lmerTest computes
//   them (Kuznetsova et al. 2017, JSS 82(13), Eq. 9 with the Hessian of the deviance in (θ, σ)).
// - Binomial with the logit link (glmer, nAGQ = 1): (θ, β) minimise the Laplace approximation of
//   the deviance (penalized_least_squares.hpp) by BOBYQA, started from the logistic regression
//   without random effects and θ = 1; Var(β̂) from the inverse of the finite-difference Hessian
//   of the deviance in (θ, β), as glmer's vcov (use.hessian); Wald z-tests.
// - Warnings as lme4 gives them: a singular fit ("boundary (singular) fit"), a gradient at the
//   optimum above lme4's tolerance 0.002 ("Model failed to converge ..."), the optimiser's limit,
//   dropped rank-deficient fixed-effect columns.
#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "analysis/model_formula.hpp"
#include "analysis/model_matrix.hpp"
#include "analysis/table.hpp"

namespace tlab::analysis {

enum class MixedFamily { Gaussian, Binomial };
std::string_view mixedFamilyName(MixedFamily family);  // "gaussian", "binomial"
MixedFamily parseMixedFamily(std::string_view text);   // throws AnalysisError

struct MixedModelRequest {
  std::string formula;
  MixedFamily family = MixedFamily::Gaussian;
  bool reml = true;  // Gaussian only: REML (lmer's default) or maximum likelihood
  ModelVariables variables;
};

struct FixedEffect {
  std::string term;   // R's coefficient name
  double estimate = 0.0;
  double stdError = 0.0;
  double statistic = 0.0;  // t (Gaussian) or z (binomial)
  double df = 0.0;         // Satterthwaite df (Gaussian); NaN for z-tests
  double p = 0.0;
};

struct VarianceComponent {
  std::string group;   // "participant", or "Residual"
  std::string term;    // "(Intercept)", "methodsmart"
  std::string term2;   // non-empty for a correlation row
  double variance = 0.0;     // variance, or the covariance for a correlation row
  double sd = 0.0;           // NaN for a correlation row
  double correlation = 0.0;  // NaN for a variance row
};

struct MixedModelResult {
  std::string formula;
  MixedFamily family = MixedFamily::Gaussian;
  bool reml = true;
  std::size_t observations = 0;
  std::vector<std::pair<std::string, std::size_t>> groups;  // grouping factor, number of levels
  std::vector<FixedEffect> fixedEffects;
  std::vector<VarianceComponent> randomEffects;
  double logLikelihood = 0.0;   // the REML log-likelihood for REML fits (as logLik(lmer))
  double aic = 0.0;
  double remlCriterion = 0.0;   // NaN unless REML
  double deviance = 0.0;        // −2 log-likelihood (the Laplace deviance for the GLMM)
  double sigma = 1.0;           // residual SD (Gaussian)
  Eigen::VectorXd theta;
  int evaluations = 0;
  bool singular = false;
  bool converged = true;
  std::vector<std::string> warnings;
  // "linear mixed model fit by REML (lme4 formula log(rt) ~ method + (1 | participant)), t-tests
  // with Satterthwaite's degrees of freedom", as a methods section would name it.
  std::string description() const;
};

MixedModelResult fitMixedModel(const Table& table, const MixedModelRequest& request);

}  // namespace tlab::analysis
