#include "analysis/sphericity.hpp"

#include <cmath>

#include "analysis/distributions.hpp"

namespace tlab::analysis {

SphericityResult sphericity(const Eigen::MatrixXd& errorSscp, double errorDf, double cellCount) {
  SphericityResult r;
  const double q = static_cast<double>(errorSscp.rows());
  const double n = errorDf;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(errorSscp, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd lambda = solver.eigenvalues();
  const double trace = lambda.sum();
  r.epsilonGG = trace * trace / (q * lambda.squaredNorm());
  r.epsilonHF = ((n + 1.0) * q * r.epsilonGG - 2.0) / (q * (n - q * r.epsilonGG));
  r.mauchlyDf = q * (q + 1.0) / 2.0 - 1.0;
  const double largest = lambda.maxCoeff();
  if (n < q || lambda.minCoeff() <= largest * 1e-14) {
    r.mauchlyW = 0.0;
    r.mauchlyChiSquared = std::nan("");
    r.mauchlyP = std::nan("");
    return r;
  }
  double logW = -q * std::log(trace / q);
  for (Eigen::Index i = 0; i < lambda.size(); ++i) logW += std::log(lambda(i));
  r.mauchlyW = std::exp(logW);
  const double rho = 1.0 - (2.0 * q * q + q + 2.0) / (6.0 * q * n);
  const double omega2 = (q + 2.0) * (q - 1.0) * (q - 2.0) * (2.0 * q * q * q + 6.0 * q * q + 3.0 * cellCount + 2.0) /
                        (288.0 * (n * q * rho) * (n * q * rho));
  const double z = -n * rho * logW;
  r.mauchlyChiSquared = z;
  const double p1 = chiSquaredUpperTail(z, r.mauchlyDf);
  const double p2 = chiSquaredUpperTail(z, r.mauchlyDf + 4.0);
  r.mauchlyP = p1 + omega2 * (p2 - p1);
  return r;
}

}  // namespace tlab::analysis
