#pragma once
// Model matrices of a mixed model from a long-format Table, as R's model.matrix and lme4's
// mkReTrms build them (Bates et al. 2015, JSS 67(1), Section 2.3):
// - a variable is numeric when every cell is a number and it is not declared a factor, otherwise a
//   factor whose levels are in file order (or as given); factors use treatment contrasts with the
//   first level as reference. Within a term a factor is coded by contrasts when the term without
//   it is in the model, by indicators otherwise (R's rule; so `0 + method` has one column per
//   level). Columns are named like R's: "(Intercept)", "methodsmart", "methodsmart:alpha0.5"
//   (first variable varying fastest);
// - X: the fixed-effect columns, columns in the span of earlier ones dropped as lme4 does
//   ("fixed-effect model matrix is rank deficient so dropping k columns / coefficients");
// - Z (Eqs. 6-7): per random-effects term the columns of its expression for each level of its
//   grouping factor, level-major ([level 1: p_k columns][level 2: ...]); the terms are ordered by
//   decreasing number of levels as mkReTrms does, which fixes the order of θ.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "analysis/model_formula.hpp"
#include "analysis/table.hpp"

namespace tlab::analysis {

struct ModelVariables {
  std::set<std::string> factors;                          // columns to treat as factors even if numeric
  std::map<std::string, std::vector<std::string>> levels;  // level order of a factor (default: file order)
};

struct RandomEffectsBlock {
  std::string group;                 // "participant", "participant:session"
  std::vector<std::string> columns;  // "(Intercept)", "methodsmart"
  std::size_t levels = 0;            // ℓ_k
  std::size_t offset = 0;            // index of its first element in u (and b)
  std::size_t thetaOffset = 0;       // index of its first element in θ
  std::size_t size() const { return columns.size(); }  // p_k
  std::size_t thetaCount() const { return size() * (size() + 1) / 2; }
};

struct MixedModelMatrices {
  std::string response;              // "log(rt)" or "correct"
  Eigen::VectorXd y;
  Eigen::MatrixXd X;                 // n × p
  std::vector<std::string> xNames;   // R's coefficient names
  std::vector<std::string> dropped;  // rank-deficient columns left out of X
  Eigen::SparseMatrix<double> Z;     // n × q
  std::vector<RandomEffectsBlock> blocks;
  std::size_t thetaSize() const;
};

// Rows with a missing value (an empty cell) in any used column are left out, as R's na.omit.
MixedModelMatrices buildMixedModelMatrices(const Table& table, const ModelFormula& formula, const ModelVariables& variables);

}  // namespace tlab::analysis
