#include "analysis/anova_design.hpp"

#include <map>

#include "analysis/analysis_error.hpp"
#include "analysis/r_moments.hpp"
#include "analysis/factor.hpp"

namespace tlab::analysis {

std::size_t AnovaDesign::cellCount() const {
  std::size_t k = 1;
  for (const auto& f : within) k *= f.levels.size();
  return k;
}

std::vector<std::size_t> withinCellLevels(const AnovaDesign& design, std::size_t cell) {
  std::vector<std::size_t> levels(design.within.size());
  for (std::size_t i = design.within.size(); i-- > 0;) {
    const std::size_t k = design.within[i].levels.size();
    levels[i] = cell % k;
    cell /= k;
  }
  return levels;
}

std::string withinCellLabel(const AnovaDesign& design, std::size_t cell) {
  const auto levels = withinCellLevels(design, cell);
  std::string label;
  for (std::size_t i = 0; i < levels.size(); ++i)
    label += (i ? ", " : "") + design.within[i].name + "=" + design.within[i].levels[levels[i]];
  return label;
}

namespace {

void requireDistinctColumns(const std::vector<std::string>& columns) {
  for (std::size_t i = 0; i < columns.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (columns[i] == columns[j])
        throw AnalysisError("column '" + columns[i] + "' is used twice in the design");
}

std::string betweenCellLabel(const std::vector<Factor>& factors, const std::vector<std::size_t>& lv) {
  std::string label;
  for (std::size_t i = 0; i < factors.size(); ++i)
    label += (i ? ", " : "") + factors[i].name + "=" + factors[i].levels[lv[i]];
  return label;
}

void checkColumns(const std::string& dv, const std::vector<std::string>& between, const std::vector<std::string>& within,
                  const std::string& subject) {
  if (!within.empty() && subject.empty())
    throw AnalysisError("within-subject factors need a subject column (--subject)");
  std::vector<std::string> used = between;
  used.insert(used.end(), within.begin(), within.end());
  used.push_back(dv);
  if (!subject.empty()) used.push_back(subject);
  requireDistinctColumns(used);
  if (between.empty() && within.empty())
    throw AnalysisError("an ANOVA needs at least one factor (--between or --within)");
}

std::vector<Factor> readFactors(const Table& table, const std::vector<std::string>& names, const char* what) {
  std::vector<Factor> factors;
  for (const auto& name : names) {
    factors.push_back(makeFactor(table, name));
    requireLevelCount(factors.back(), 2, SIZE_MAX, what);
  }
  return factors;
}

// Subject of each row: the subject column, or the row itself; fills design.subjects.
std::vector<std::size_t> subjectOfRows(const Table& table, const std::string& subject, AnovaDesign& design) {
  std::vector<std::size_t> subjectOfRow(table.rowCount());
  if (subject.empty()) {
    for (std::size_t r = 0; r < table.rowCount(); ++r) {
      subjectOfRow[r] = r;
      design.subjects.push_back("row " + table.where(r));
    }
  } else {
    const Factor s = makeFactor(table, subject);
    subjectOfRow = s.codes;
    design.subjects = s.levels;
  }
  return subjectOfRow;
}

// Between group of each subject (must be constant within a subject).
void assignBetweenLevels(const Table& table, const std::vector<Factor>& betweenFactors,
                         const std::vector<std::size_t>& subjectOfRow, AnovaDesign& design) {
  const std::size_t n = design.subjects.size();
  design.betweenLevels.assign(n, std::vector<std::size_t>(betweenFactors.size(), SIZE_MAX));
  std::vector<std::size_t> firstRow(n, SIZE_MAX);
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    const std::size_t s = subjectOfRow[r];
    if (firstRow[s] == SIZE_MAX) firstRow[s] = r;
    for (std::size_t f = 0; f < betweenFactors.size(); ++f) {
      const std::size_t level = betweenFactors[f].codes[r];
      std::size_t& known = design.betweenLevels[s][f];
      if (known == SIZE_MAX) known = level;
      if (known != level)
        throw AnalysisError(table.where(r) + ": subject '" + design.subjects[s] + "' is in " +
                            betweenFactors[f].name + "=" + betweenFactors[f].levels[level] +
                            " here but in " + betweenFactors[f].name + "=" +
                            betweenFactors[f].levels[known] + " at " + table.where(firstRow[s]) +
                            " (a between-subject factor must be constant within a subject)");
    }
  }
}

// Cell means per subject, as R's mean() computes them (replicates of a subject in a cell).
void cellMeans(const Table& table, const std::vector<double>& values, const std::vector<Factor>& withinFactors,
               const std::vector<std::size_t>& subjectOfRow, AnovaDesign& design) {
  const std::size_t cells = design.cellCount();
  const std::size_t n = design.subjects.size();
  std::vector<std::vector<double>> cellValues(n * cells);
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    std::size_t cell = 0;
    for (const auto& f : withinFactors) cell = cell * f.levels.size() + f.codes[r];
    cellValues[subjectOfRow[r] * cells + cell].push_back(values[r]);
  }
  design.y.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(cells));
  for (std::size_t s = 0; s < n; ++s)
    for (std::size_t c = 0; c < cells; ++c) {
      const std::vector<double>& replicates = cellValues[s * cells + c];
      if (replicates.empty())
        throw AnalysisError("unbalanced within-subject data: subject '" + design.subjects[s] +
                            "' has no observation in cell " + withinCellLabel(design, c) +
                            " (every subject needs every within-subject cell)");
      design.maxReplicates = std::max(design.maxReplicates, replicates.size());
      design.y(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(c)) = rMean(replicates);
    }
}

// Every between-subject cell needs subjects (otherwise the model is rank deficient).
void requireFilledBetweenCells(const std::vector<Factor>& betweenFactors, const AnovaDesign& design) {
  if (betweenFactors.empty()) return;
  std::map<std::vector<std::size_t>, std::size_t> perCell;
  for (const auto& lv : design.betweenLevels) ++perCell[lv];
  std::vector<std::size_t> lv(betweenFactors.size(), 0);
  while (true) {
    if (perCell[lv] == 0)
      throw AnalysisError("between-subject cell " + betweenCellLabel(betweenFactors, lv) +
                          " has no subjects");
    std::size_t f = lv.size();
    while (f-- > 0) {
      if (++lv[f] < betweenFactors[f].levels.size()) break;
      lv[f] = 0;
    }
    if (f == SIZE_MAX) break;
  }
}

}  // namespace

AnovaDesign makeAnovaDesign(const Table& table, const std::string& dv,
                            const std::vector<std::string>& between,
                            const std::vector<std::string>& within, const std::string& subject) {
  checkColumns(dv, between, within, subject);
  const std::vector<double> values = table.numericColumn(dv);
  if (table.rowCount() == 0) throw AnalysisError(table.source() + ": no data rows");
  const std::vector<Factor> betweenFactors = readFactors(table, between, "a between-subject factor");
  const std::vector<Factor> withinFactors = readFactors(table, within, "a within-subject factor");

  AnovaDesign design;
  design.dv = dv;
  for (const auto& f : betweenFactors) design.between.push_back({f.name, f.levels});
  for (const auto& f : withinFactors) design.within.push_back({f.name, f.levels});
  const std::vector<std::size_t> subjectOfRow = subjectOfRows(table, subject, design);
  assignBetweenLevels(table, betweenFactors, subjectOfRow, design);
  cellMeans(table, values, withinFactors, subjectOfRow, design);
  requireFilledBetweenCells(betweenFactors, design);
  return design;
}

}  // namespace tlab::analysis
