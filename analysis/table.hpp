#pragma once
// Table: a long-format data table, i.e. named columns of values with one row per observation.
// Cells are kept as text (exactly as read, so factor labels survive unchanged) and converted to
// numbers on demand; every row remembers where it came from (file and line, or a database row)
// so that a bad value is reported as "study.csv:17: column 'time': 'abc' is not a number".
//
// This is the only input of the statistics: the CSV reader builds one, and the study library's
// SQLite adapter builds one with addColumn()/addRow().
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tlab::analysis {

class Table {
 public:
  // `source` names the origin in messages ("results.csv", "study.db").
  Table(std::string source, std::vector<std::string> columnNames);

  // Appends a row; `origin` is its line number in the source (or any 1-based row id).
  void addRow(std::vector<std::string> cells, std::size_t origin);
  // Appends a numeric column (formatted with the shortest round-trip representation, so
  // number(row, column) returns the double bit for bit). Its size must equal rowCount().
  void addNumericColumn(std::string name, std::span<const double> values);
  void addTextColumn(std::string name, std::vector<std::string> values);

  const std::string& source() const { return source_; }
  std::size_t rowCount() const { return origins_.size(); }
  std::size_t columnCount() const { return names_.size(); }
  const std::vector<std::string>& columnNames() const { return names_; }

  bool hasColumn(std::string_view name) const;
  // Index of a column; throws AnalysisError naming the available columns.
  std::size_t columnIndex(std::string_view name) const;

  const std::string& text(std::size_t row, std::size_t column) const;
  // The cell as a finite double; throws "source:line: column 'c': 'x' is not a number".
  double number(std::size_t row, std::size_t column) const;
  std::vector<double> numericColumn(std::string_view name) const;
  std::vector<std::string> textColumn(std::string_view name) const;

  // "source:line" of a row, for messages; origin(): its line (or row id) alone.
  std::string where(std::size_t row) const;
  std::size_t origin(std::size_t row) const { return origins_.at(row); }

  // The rows whose cell in `column` is `value` (same columns, same origins).
  Table rowsWhere(std::string_view column, std::string_view value) const;

 private:
  std::string source_;
  std::vector<std::string> names_;
  std::vector<std::vector<std::string>> columns_;  // columns_[column][row]
  std::vector<std::size_t> origins_;
};

// Parses a whole cell as a finite double (surrounding blanks allowed); false if it is not one.
bool parseDouble(std::string_view text, double& value);

}  // namespace tlab::analysis
