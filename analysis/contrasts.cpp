#include "analysis/contrasts.hpp"

#include <cmath>

namespace tlab::analysis {

Eigen::MatrixXd orthonormalHelmert(std::size_t k) {
  const auto n = static_cast<Eigen::Index>(k);
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n - 1);
  for (Eigen::Index j = 0; j < n - 1; ++j) {
    const double norm = std::sqrt(static_cast<double>((j + 1) * (j + 2)));
    for (Eigen::Index i = 0; i <= j; ++i) c(i, j) = 1.0 / norm;
    c(j + 1, j) = -static_cast<double>(j + 1) / norm;
  }
  return c;
}

Eigen::MatrixXd withinTermTransform(const std::vector<std::size_t>& levelCounts,
                                    const std::vector<bool>& inTerm) {
  Eigen::MatrixXd t = Eigen::MatrixXd::Ones(1, 1);
  for (std::size_t f = 0; f < levelCounts.size(); ++f) {
    const auto k = static_cast<Eigen::Index>(levelCounts[f]);
    const Eigen::MatrixXd factor = inTerm[f]
                                       ? orthonormalHelmert(levelCounts[f])
                                       : Eigen::MatrixXd::Constant(k, 1, 1.0 / std::sqrt(static_cast<double>(k)));
    Eigen::MatrixXd product(t.rows() * factor.rows(), t.cols() * factor.cols());
    for (Eigen::Index i = 0; i < t.rows(); ++i)
      for (Eigen::Index j = 0; j < t.cols(); ++j)
        product.block(i * factor.rows(), j * factor.cols(), factor.rows(), factor.cols()) = t(i, j) * factor;
    t = std::move(product);
  }
  return t;
}

Eigen::MatrixXd sumToZeroCoding(std::size_t k) {
  const auto n = static_cast<Eigen::Index>(k);
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n - 1);
  for (Eigen::Index i = 0; i < n - 1; ++i) c(i, i) = 1.0;
  c.row(n - 1).setConstant(-1.0);
  return c;
}

}  // namespace tlab::analysis
