#pragma once
// AnovaDesign: a long-format Table reshaped into the form every ANOVA here works on — one row per
// subject, one column per within-subject cell (the combination of the within factors' levels,
// last factor varying fastest), and each subject's between-subject group.
//
// Several observations of one subject in one cell (e.g. Elmqvist's 3 trials per condition) are
// averaged first, as in a repeated-measures analysis of subject means (the usual practice and
// what ez::ezANOVA does); `maxReplicates` records that it happened.
#include <Eigen/Dense>
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/table.hpp"

namespace tlab::analysis {

struct FactorLevels {
  std::string name;
  std::vector<std::string> levels;
};

struct AnovaDesign {
  std::string dv;
  std::vector<FactorLevels> between;
  std::vector<FactorLevels> within;
  std::vector<std::string> subjects;
  std::vector<std::vector<std::size_t>> betweenLevels;  // [subject][between factor] → level index
  Eigen::MatrixXd y;                                    // [subject][within cell]
  std::size_t maxReplicates = 1;  // most observations averaged into one subject × cell value

  std::size_t cellCount() const;  // number of within cells (1 without within factors)
};

// Builds the design. `subject` may be empty only when there are no within factors (then every
// row is its own subject). Throws AnalysisError for: a missing column, a non-numeric dv
// (file:line), a factor with one level, a subject that appears in two between groups, a subject
// missing a within cell ("unbalanced within-subject data: subject 'S3' has no observation in cell
// time=t2"), and an empty between-subject cell.
AnovaDesign makeAnovaDesign(const Table& table, const std::string& dv,
                            const std::vector<std::string>& between,
                            const std::vector<std::string>& within, const std::string& subject);

// "A=a1, B=b2" for a within cell index, "" if there are no within factors.
std::string withinCellLabel(const AnovaDesign& design, std::size_t cell);
// Level indices of a within cell (first factor first).
std::vector<std::size_t> withinCellLevels(const AnovaDesign& design, std::size_t cell);

}  // namespace tlab::analysis
