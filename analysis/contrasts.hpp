#pragma once
// Contrast and coding matrices for the general linear model behind the ANOVAs.
#include <Eigen/Dense>
#include <cstddef>
#include <vector>

namespace tlab::analysis {

// k × (k-1) orthonormal Helmert contrasts: column j compares level j+1 with the mean of levels
// 0..j, scaled to unit length. Any orthonormal basis of the contrasts gives the same sums of
// squares, ε and Mauchly W (they are invariant under orthogonal rotation; Maxwell & Delaney 2004,
// Ch. 13), so the choice only has to be orthonormal.
Eigen::MatrixXd orthonormalHelmert(std::size_t k);

// The transformation of the within-subject cells (K = Π k_f columns, last factor fastest) for one
// within term: the Kronecker product over the within factors of the orthonormal contrasts
// (factors in the term) or the normalized mean 1/√k_f·1 (factors not in the term). The empty term
// gives the K × 1 normalized mean, i.e. the between-subject stratum.
Eigen::MatrixXd withinTermTransform(const std::vector<std::size_t>& levelCounts,
                                    const std::vector<bool>& inTerm);

// k × (k-1) sum-to-zero ("deviation", R's contr.sum) coding: level i < k-1 → e_i, last level → -1.
Eigen::MatrixXd sumToZeroCoding(std::size_t k);

}  // namespace tlab::analysis
