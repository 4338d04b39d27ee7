#pragma once
// Bound-constrained derivative-free minimisation by Powell's BOBYQA (2009), through NLopt
// (NLOPT_LN_BOBYQA) — the algorithm of lme4's default optimizer for lmer (nloptwrap). Used for the
// covariance parameters θ (and β for the GLMM) of a mixed model.
#include <Eigen/Dense>
#include <functional>
#include <string>

namespace tlab::analysis {

struct BobyqaOptions {
  double ftolAbs = 1e-12;   // stop when the objective changes by less than this
  double xtolAbs = 1e-10;   // ... or every parameter by less than this
  int maxEvaluations = 100000;
  Eigen::VectorXd initialStep;  // empty: NLopt's heuristic
};

struct BobyqaResult {
  Eigen::VectorXd x;
  double value = 0.0;
  int evaluations = 0;
  bool converged = true;  // false when the evaluation limit was reached or NLopt failed
  std::string message;
};

BobyqaResult minimizeBobyqa(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& start,
                            const Eigen::VectorXd& lower, const BobyqaOptions& options = {});

}  // namespace tlab::analysis
