#pragma once
// Gradients, Hessians and Jacobians by central differences with Richardson extrapolation, as R's
// numDeriv (Gilbert & Varadhan) computes them with method "Richardson" (d = 1e-4 relative step,
// r = 4 halvings): the derivatives lmerTest takes of the deviance and of Var(β̂) in the variance
// parameters (Kuznetsova, Brockhoff & Christensen 2017, JSS 82(13), Section 3.2), and lme4's
// Hessian of the GLMM deviance for the standard errors.
#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace tlab::analysis {

using ScalarFunction = std::function<double(const Eigen::VectorXd&)>;
using MatrixFunction = std::function<Eigen::MatrixXd(const Eigen::VectorXd&)>;

// The first step h for x: relative·|x|, or `absolute` when |x| < zeroTolerance; then `levels`
// halvings. The default is numDeriv's (d = 1e-4, eps = 1e-4, zero.tol ≈ 1.8e-5, r = 4). A function
// computed by an inner iteration (the Laplace deviance after PIRLS) carries rounding noise ε, and
// a second difference amplifies it by 1/h²: such functions need larger steps (`noisySteps`).
struct DerivativeSteps {
  double relative = 1e-4;
  double absolute = 1e-4;
  double zeroTolerance = 1.7817416127494959e-5;
  int levels = 4;
};
// h = 1e-2 for every parameter, three levels (h, h/2, h/4): noise 1e-10 costs 1e-5 in H.
inline DerivativeSteps noisySteps() { return {0.0, 1e-2, 1e300, 3}; }

Eigen::VectorXd richardsonGradient(const ScalarFunction& f, const Eigen::VectorXd& x, const DerivativeSteps& steps = {});
Eigen::MatrixXd richardsonHessian(const ScalarFunction& f, const Eigen::VectorXd& x, const DerivativeSteps& steps = {});
// ∂F/∂x_k for each k.
std::vector<Eigen::MatrixXd> richardsonJacobian(const MatrixFunction& f, const Eigen::VectorXd& x, const DerivativeSteps& steps = {});

}  // namespace tlab::analysis
