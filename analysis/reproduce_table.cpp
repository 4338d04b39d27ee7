#include "analysis/reproduce_table.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/analysis_error.hpp"
#include "analysis/csv_reader.hpp"

namespace tlab::analysis {

namespace {

// The cell exactly as printed; Table::number validates it first, naming file, line and column.
ReportedValue printedNumber(const Table& table, std::size_t row, const char* column) {
  const std::size_t c = table.columnIndex(column);
  table.number(row, c);
  return ReportedValue::parse(table.text(row, c));
}

std::optional<ReportedValue> optionalNumber(const Table& table, std::size_t row, const char* column) {
  if (!table.hasColumn(column)) return std::nullopt;
  const std::string& cell = table.text(row, table.columnIndex(column));
  if (cell.find_first_not_of(" \t") == std::string::npos) return std::nullopt;
  return printedNumber(table, row, column);
}

double groupSize(const Table& table, std::size_t row, const char* column) {
  const double n = table.number(row, table.columnIndex(column));
  if (n < 2 || n != std::floor(n))
    throw AnalysisError(table.where(row) + ": column '" + column + "': a group size must be an integer >= 2");
  return n;
}

// Variance and its rounding interval from a printed variance or a printed SD.
void spread(const Table& table, std::size_t row, int group, double& variance, Interval& range) {
  const bool sd = !table.hasColumn(group == 1 ? "var1" : "var2");
  const ReportedValue v = printedNumber(table, row, sd ? (group == 1 ? "sd1" : "sd2") : (group == 1 ? "var1" : "var2"));
  if (v.value <= 0) throw AnalysisError(table.where(row) + ": a variance or SD must be positive");
  variance = sd ? v.value * v.value : v.value;
  range = sd ? square(v.interval()) : v.interval();
  range.lo = std::max(range.lo, 0.0);
  if (range.lo == 0.0) range.lo = std::min(variance, 1e-300);  // keep the ratio of variances finite
}

std::string label(const Table& table, std::size_t row, const char* column, const char* fallback) {
  return table.hasColumn(column) ? table.text(row, table.columnIndex(column)) : fallback;
}

PrintedTTest readRow(const Table& table, std::size_t row) {
  PrintedTTest p;
  p.mean1 = printedNumber(table, row, "mean1");
  p.mean2 = printedNumber(table, row, "mean2");
  p.n1 = groupSize(table, row, "n1");
  p.n2 = groupSize(table, row, "n2");
  spread(table, row, 1, p.variance1, p.variance1Range);
  spread(table, row, 2, p.variance2, p.variance2Range);
  p.df = optionalNumber(table, row, "df");
  p.t = optionalNumber(table, row, "t");
  p.p = optionalNumber(table, row, "p");
  if (const auto tails = optionalNumber(table, row, "p_tails")) {
    if (tails->value != 1.0 && tails->value != 2.0)
      throw AnalysisError(table.where(row) + ": column 'p_tails': must be 1 or 2");
    p.pTails = static_cast<int>(tails->value);
  }
  return p;
}

}  // namespace

std::vector<TableComparison> readComparisonTable(const std::string& path) {
  const Table table = readCsvFile(path);
  if (!table.hasColumn("var1") && !table.hasColumn("sd1"))
    throw AnalysisError(path + ": give the spread as columns var1, var2 or sd1, sd2");
  std::vector<TableComparison> rows;
  for (std::size_t row = 0; row < table.rowCount(); ++row) {
    TableComparison c;
    c.first = label(table, row, "first", "group 1");
    c.second = label(table, row, "second", "group 2");
    c.where = table.where(row);
    c.printed = readRow(table, row);
    rows.push_back(c);
  }
  if (rows.empty()) throw AnalysisError(path + ": no comparisons (the table has a header only)");
  return rows;
}

std::vector<TableComparison> reproduceTable(const std::string& path) {
  std::vector<TableComparison> rows = readComparisonTable(path);
  for (auto& row : rows) {
    row.checks.push_back(checkTwoSampleHypothesis(row.printed, TTestKind::Welch));
    row.checks.push_back(checkTwoSampleHypothesis(row.printed, TTestKind::Student));
    if (row.printed.n1 == row.printed.n2) row.checks.push_back(checkPairedHypothesis(row.printed));
  }
  return rows;
}

}  // namespace tlab::analysis
