// The fit of a mixed model (mixed_model.hpp): the optimisation of θ (and β for the GLMM), then the
// estimates, their covariance, the tests and lme4's checks. The inner problems (PLS, PIRLS) are in
// penalized_least_squares.cpp.
#include "analysis/mixed_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/analysis_error.hpp"
#include "analysis/bobyqa.hpp"
#include "analysis/distributions.hpp"
#include "analysis/number_format.hpp"
#include "analysis/numerical_derivatives.hpp"
#include "analysis/penalized_least_squares.hpp"

namespace tlab::analysis {

namespace {

constexpr double kSingularTolerance = 1e-4;  // lme4's isSingular(tol = 1e-4)
constexpr double kGradientTolerance = 2e-3;  // lme4's check.conv.grad tol
// lmerTest takes numDeriv's steps (1e-4·|x|, four halvings); the deviance carries rounding noise of
// ~1e-15·|deviance|, which the smallest of those steps turns into ~1e-3 of the Hessian. Steps ten
// times larger keep the noise at 1e-5 and Richardson's extrapolation the truncation error lower still.
const DerivativeSteps kSatterthwaiteSteps{1e-3, 1e-3, 1.7817416127494959e-5, 4};

std::size_t size(const Eigen::VectorXd& v) { return static_cast<std::size_t>(v.size()); }

// Σ_k = σ² T_k T_kᵀ as lme4's VarCorr: the variances, then the correlations of each block.
std::vector<VarianceComponent> varianceComponents(const MixedModelMatrices& m, const Eigen::VectorXd& theta, double sigma) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<VarianceComponent> out;
  for (const auto& b : m.blocks) {
    const Eigen::MatrixXd t = blockFactor(b, theta);
    const Eigen::MatrixXd sigmaK = sigma * sigma * t * t.transpose();
    for (std::size_t i = 0; i < b.size(); ++i) {
      const auto ii = static_cast<Eigen::Index>(i);
      out.push_back({b.group, b.columns[i], "", sigmaK(ii, ii), std::sqrt(sigmaK(ii, ii)), nan});
    }
    for (std::size_t j = 0; j < b.size(); ++j)
      for (std::size_t i = j + 1; i < b.size(); ++i) {
        const auto ii = static_cast<Eigen::Index>(i), jj = static_cast<Eigen::Index>(j);
        const double cov = sigmaK(ii, jj), denominator = std::sqrt(sigmaK(ii, ii) * sigmaK(jj, jj));
        out.push_back({b.group, b.columns[j], b.columns[i], cov, nan, denominator > 0 ? cov / denominator : nan});
      }
  }
  return out;
}

// lme4's isSingular: a diagonal element of some T_k (lower bound 0) below 1e-4.
bool isSingular(const Eigen::VectorXd& theta, const Eigen::VectorXd& lower) {
  for (Eigen::Index k = 0; k < theta.size(); ++k)
    if (lower(k) == 0.0 && theta(k) < kSingularTolerance) return true;
  return false;
}

// lme4's checkConv: the gradient g scaled by the Hessian H (solve(chol(H), g)), its smaller
// magnitude against the raw gradient, compared with 0.002; parameters on a bound are left out.
void checkGradient(const Eigen::VectorXd& gradient, const Eigen::MatrixXd& hessian, const Eigen::VectorXd& x,
                   const Eigen::VectorXd& lower, MixedModelResult& r) {
  std::vector<Eigen::Index> free;
  for (Eigen::Index k = 0; k < x.size(); ++k)
    if (!(lower(k) == 0.0 && x(k) < kSingularTolerance)) free.push_back(k);
  if (free.empty()) return;
  const auto n = static_cast<Eigen::Index>(free.size());
  Eigen::VectorXd g(n);
  Eigen::MatrixXd h(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    g(i) = gradient(free[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < n; ++j) h(i, j) = hessian(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
  }
  const Eigen::LLT<Eigen::MatrixXd> chol(h);
  Eigen::VectorXd scaled = g;
  if (chol.info() == Eigen::Success) scaled = chol.matrixU().solve(g);  // R: solve(chol(H), g), chol(H) = U, H = UᵀU
  double worst = 0.0;
  Eigen::Index at = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double v = std::min(std::fabs(scaled(k)), std::fabs(g(k)));
    if (v > worst) worst = v, at = free[static_cast<std::size_t>(k)];
  }
  if (worst > kGradientTolerance) {
    r.converged = false;
    r.warnings.push_back("Model failed to converge with max|grad| = " + formatNumber(worst, 6) + " (tol = 0.002, component " +
                         std::to_string(at + 1) + ")");
  }
}

void addCommonWarnings(const MixedModelMatrices& m, const BobyqaResult& opt, const Eigen::VectorXd& lower, MixedModelResult& r) {
  if (!m.dropped.empty()) {
    std::string list;
    for (const auto& d : m.dropped) list += (list.empty() ? "" : ", ") + d;
    r.warnings.push_back("fixed-effect model matrix is rank deficient so dropping " + std::to_string(m.dropped.size()) +
                         " columns / coefficients (" + list + ")");
  }
  if (!opt.converged) {
    r.converged = false;
    r.warnings.push_back(opt.message);
  }
  r.singular = isSingular(opt.x.head(lower.size()), lower);
  if (r.singular) r.warnings.push_back("boundary (singular) fit: see help('isSingular')");
}

MixedModelResult describeModel(const MixedModelMatrices& m, const MixedModelRequest& request, const ModelFormula& formula) {
  MixedModelResult r;
  r.formula = formula.text;
  r.family = request.family;
  r.reml = request.family == MixedFamily::Gaussian && request.reml;
  r.observations = size(m.y);
  for (const auto& b : m.blocks)
    if (std::none_of(r.groups.begin(), r.groups.end(), [&](const auto& g) { return g.first == b.group; }))
      r.groups.emplace_back(b.group, b.levels);
  return r;
}

// Satterthwaite's df of each coefficient as lmerTest: df = 2 (ℓᵀCℓ)² / (gᵀ A g), C = Var(β̂),
// g_k = ℓᵀ (∂C/∂φ_k) ℓ, A = 2 H⁻¹ with H the Hessian of the deviance in φ = (θ, σ).
std::vector<double> satterthwaiteDf(const MixedModelMatrices& m, bool reml, const Eigen::VectorXd& theta, double sigma,
                                    const Eigen::MatrixXd& vcov, MixedModelResult& r) {
  const std::size_t n = size(m.y), p = m.xNames.size();
  Eigen::VectorXd phi(theta.size() + 1);
  phi << theta, sigma;
  const auto split = [&](const Eigen::VectorXd& v) { return std::make_pair(Eigen::VectorXd(v.head(theta.size())), v(theta.size())); };
  const ScalarFunction deviance = [&](const Eigen::VectorXd& v) {
    const auto [t, s] = split(v);
    return devianceAtSigma(solveLinearMixedModel(m, t), n, p, reml, s);
  };
  const MatrixFunction covariance = [&](const Eigen::VectorXd& v) {
    const auto [t, s] = split(v);
    return Eigen::MatrixXd(s * s * solveLinearMixedModel(m, t).RXtRX.inverse());
  };
  const Eigen::MatrixXd h = richardsonHessian(deviance, phi, kSatterthwaiteSteps);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(h);
  std::vector<double> df(p, std::numeric_limits<double>::quiet_NaN());
  if (eigen.eigenvalues().minCoeff() <= 1e-6 * std::max(1.0, eigen.eigenvalues().maxCoeff())) {
    r.warnings.push_back("the Hessian of the deviance in the variance parameters is not positive definite: no Satterthwaite df");
    return df;
  }
  const Eigen::MatrixXd a = 2.0 * h.inverse();
  const std::vector<Eigen::MatrixXd> jacobian = richardsonJacobian(covariance, phi, kSatterthwaiteSteps);
  for (std::size_t j = 0; j < p; ++j) {
    const auto jj = static_cast<Eigen::Index>(j);
    Eigen::VectorXd g(phi.size());
    for (Eigen::Index k = 0; k < phi.size(); ++k) g(k) = jacobian[static_cast<std::size_t>(k)](jj, jj);
    df[j] = 2.0 * vcov(jj, jj) * vcov(jj, jj) / g.dot(a * g);
  }
  return df;
}

MixedModelResult fitLinear(const MixedModelMatrices& m, const MixedModelRequest& request, const ModelFormula& formula) {
  MixedModelResult r = describeModel(m, request, formula);
  const std::size_t n = size(m.y), p = m.xNames.size();
  if (n <= p) throw AnalysisError("mixed model: " + std::to_string(n) + " observations for " + std::to_string(p) + " fixed effects");
  const ScalarFunction objective = [&](const Eigen::VectorXd& theta) {
    return profiledDeviance(solveLinearMixedModel(m, theta), n, p, r.reml);
  };
  const Eigen::VectorXd lower = thetaLowerBounds(m);
  const BobyqaResult opt = minimizeBobyqa(objective, thetaStart(m), lower);
  r.theta = opt.x;
  r.evaluations = opt.evaluations;
  addCommonWarnings(m, opt, lower, r);
  checkGradient(richardsonGradient(objective, opt.x), richardsonHessian(objective, opt.x), opt.x, lower, r);
  const PlsSolution s = solveLinearMixedModel(m, r.theta);
  r.deviance = opt.value;
  r.sigma = std::sqrt(s.pwrss / static_cast<double>(r.reml ? n - p : n));  // Eq. 40 or Eq. 33
  const Eigen::MatrixXd vcov = r.sigma * r.sigma * s.RXtRX.inverse();       // Eq. 54
  const std::vector<double> df = satterthwaiteDf(m, r.reml, r.theta, r.sigma, vcov, r);
  for (std::size_t j = 0; j < p; ++j) {
    const auto jj = static_cast<Eigen::Index>(j);
    FixedEffect e{m.xNames[j], s.beta(jj), std::sqrt(vcov(jj, jj))};
    e.statistic = e.estimate / e.stdError;
    e.df = df[j];
    e.p = std::isfinite(e.df) ? studentTPValue(e.statistic, e.df, Alternative::TwoSided) : std::numeric_limits<double>::quiet_NaN();
    r.fixedEffects.push_back(e);
  }
  r.randomEffects = varianceComponents(m, r.theta, r.sigma);
  r.randomEffects.push_back({"Residual", "", "", r.sigma * r.sigma, r.sigma, std::numeric_limits<double>::quiet_NaN()});
  r.remlCriterion = r.reml ? opt.value : std::numeric_limits<double>::quiet_NaN();
  r.logLikelihood = -opt.value / 2.0;
  r.aic = opt.value + 2.0 * static_cast<double>(p + size(r.theta) + 1);
  return r;
}

// Logistic regression without random effects by IRLS: the starting β of the GLMM.
Eigen::VectorXd logisticRegression(const MixedModelMatrices& m) {
  Eigen::VectorXd beta = Eigen::VectorXd::Zero(m.X.cols());
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Eigen::ArrayXd mu = 1.0 / (1.0 + (-(m.X * beta).array()).exp());
    const Eigen::ArrayXd w = (mu * (1.0 - mu)).max(1e-10);
    const Eigen::MatrixXd xtwx = m.X.transpose() * w.matrix().asDiagonal() * m.X;
    const Eigen::VectorXd step = xtwx.ldlt().solve(m.X.transpose() * (m.y.array() - mu).matrix());
    beta += step;
    if (step.lpNorm<Eigen::Infinity>() < 1e-10) break;
  }
  return beta;
}

MixedModelResult fitBinomial(const MixedModelMatrices& m, const MixedModelRequest& request, const ModelFormula& formula) {
  for (Eigen::Index i = 0; i < m.y.size(); ++i)
    if (m.y(i) != 0.0 && m.y(i) != 1.0)
      throw AnalysisError("binomial mixed model: the response '" + m.response + "' must be 0 or 1, found " + formatNumber(m.y(i), 6));
  MixedModelResult r = describeModel(m, request, formula);
  const Eigen::Index nt = static_cast<Eigen::Index>(m.thetaSize()), p = m.X.cols();
  // Each evaluation starts PIRLS at the previous evaluation's mode (lme4 keeps u between calls too).
  Eigen::VectorXd lastMode;
  const ScalarFunction objective = [&](const Eigen::VectorXd& x) {
    LaplaceSolution s = laplaceDeviance(m, x.head(nt), x.tail(p), &lastMode);
    lastMode = std::move(s.u);
    return s.deviance;
  };
  Eigen::VectorXd start(nt + p), lower(nt + p), step(nt + p);
  const Eigen::VectorXd beta0 = logisticRegression(m);
  start << thetaStart(m), beta0;
  lower << thetaLowerBounds(m), Eigen::VectorXd::Constant(p, -std::numeric_limits<double>::infinity());
  step << Eigen::VectorXd::Constant(nt, 0.2), (0.1 * beta0.array().abs()).max(0.05).matrix();
  BobyqaOptions options;
  options.initialStep = step;
  const BobyqaResult first = minimizeBobyqa(objective, start, lower, options);
  // The Laplace deviance is flat along ridges of (θ, β): a second run from the first's optimum with
  // a fresh, small trust region moves on where the first stopped (7e-5 of β on binary_slopes).
  options.initialStep = Eigen::VectorXd::Constant(nt + p, 1e-3);
  BobyqaResult opt = minimizeBobyqa(objective, first.x, lower, options);
  opt.evaluations += first.evaluations;
  if (!first.converged) opt.converged = false, opt.message = first.message;
  r.theta = opt.x.head(nt);
  r.evaluations = opt.evaluations;
  addCommonWarnings(m, opt, thetaLowerBounds(m), r);
  // Var(β̂): the β block of (H/2)⁻¹, H the Hessian of the deviance in (θ, β) (glmer's vcov).
  const Eigen::MatrixXd h = richardsonHessian(objective, opt.x, noisySteps());
  checkGradient(richardsonGradient(objective, opt.x, noisySteps()), h, opt.x, lower, r);
  Eigen::MatrixXd vcov = 2.0 * h.inverse();
  if (!std::isfinite(vcov.sum()) || vcov.bottomRightCorner(p, p).diagonal().minCoeff() <= 0.0) {
    r.warnings.push_back("the Hessian of the deviance is not positive definite: standard errors from R_X instead");
    const Eigen::MatrixXd hb =
        richardsonHessian([&](const Eigen::VectorXd& b) { return laplaceDeviance(m, r.theta, b).deviance; }, opt.x.tail(p), noisySteps());
    vcov = Eigen::MatrixXd::Zero(nt + p, nt + p);
    vcov.bottomRightCorner(p, p) = 2.0 * hb.inverse();
  }
  for (Eigen::Index j = 0; j < p; ++j) {
    FixedEffect e{m.xNames[static_cast<std::size_t>(j)], opt.x(nt + j), std::sqrt(vcov(nt + j, nt + j))};
    e.statistic = e.estimate / e.stdError;
    e.df = std::numeric_limits<double>::quiet_NaN();
    e.p = normalPValue(e.statistic, Alternative::TwoSided);
    r.fixedEffects.push_back(e);
  }
  r.randomEffects = varianceComponents(m, r.theta, 1.0);
  r.deviance = opt.value;
  r.remlCriterion = std::numeric_limits<double>::quiet_NaN();
  r.logLikelihood = -opt.value / 2.0;
  r.aic = opt.value + 2.0 * static_cast<double>(nt + p);
  return r;
}

}  // namespace

std::string_view mixedFamilyName(MixedFamily family) { return family == MixedFamily::Gaussian ? "gaussian" : "binomial"; }

MixedFamily parseMixedFamily(std::string_view text) {
  if (text == "gaussian") return MixedFamily::Gaussian;
  if (text == "binomial") return MixedFamily::Binomial;
  throw AnalysisError("'" + std::string(text) + "' is not a family: use gaussian or binomial");
}

std::string MixedModelResult::description() const {
  if (family == MixedFamily::Gaussian)
    return std::string("linear mixed model fit by ") + (reml ? "REML" : "maximum likelihood") + " (lme4 formula " + formula +
           "; Bates et al. 2015), t-tests with Satterthwaite's degrees of freedom (as lmerTest)";
  return "generalized linear mixed model, binomial family with logit link, fit by maximum likelihood with the Laplace "
         "approximation (lme4 formula " + formula + "; glmer, nAGQ = 1), Wald z-tests";
}

MixedModelResult fitMixedModel(const Table& table, const MixedModelRequest& request) {
  const ModelFormula formula = parseModelFormula(request.formula);
  const MixedModelMatrices m = buildMixedModelMatrices(table, formula, request.variables);
  if (m.xNames.empty()) throw AnalysisError("mixed model: no fixed effects (not even an intercept)");
  return request.family == MixedFamily::Gaussian ? fitLinear(m, request, formula) : fitBinomial(m, request, formula);
}

}  // namespace tlab::analysis
