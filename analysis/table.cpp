#include "analysis/table.hpp"

#include <charconv>
#include <cmath>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

std::string_view trimBlanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::string formatShortest(double x) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

}  // namespace

bool parseDouble(std::string_view text, double& value) {
  text = trimBlanks(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  double parsed = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return false;
  if (!std::isfinite(parsed)) return false;
  value = parsed;
  return true;
}

Table::Table(std::string source, std::vector<std::string> columnNames)
    : source_(std::move(source)), names_(std::move(columnNames)), columns_(names_.size()) {
  for (std::size_t i = 0; i < names_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (names_[i] == names_[j])
        throw AnalysisError(source_ + ": duplicate column name '" + names_[i] + "'");
}

void Table::addRow(std::vector<std::string> cells, std::size_t origin) {
  if (cells.size() != names_.size())
    throw AnalysisError(source_ + ":" + std::to_string(origin) + ": expected " +
                        std::to_string(names_.size()) + " fields, found " +
                        std::to_string(cells.size()));
  for (std::size_t c = 0; c < cells.size(); ++c) columns_[c].push_back(std::move(cells[c]));
  origins_.push_back(origin);
}

void Table::addNumericColumn(std::string name, std::span<const double> values) {
  std::vector<std::string> text;
  text.reserve(values.size());
  for (const double v : values) text.push_back(formatShortest(v));
  addTextColumn(std::move(name), std::move(text));
}

void Table::addTextColumn(std::string name, std::vector<std::string> values) {
  if (hasColumn(name)) throw AnalysisError(source_ + ": duplicate column name '" + name + "'");
  if (!names_.empty() && values.size() != rowCount())
    throw AnalysisError(source_ + ": column '" + name + "' has " + std::to_string(values.size()) +
                        " values but the table has " + std::to_string(rowCount()) + " rows");
  if (names_.empty())
    for (std::size_t r = 0; r < values.size(); ++r) origins_.push_back(r + 1);
  names_.push_back(std::move(name));
  columns_.push_back(std::move(values));
}

bool Table::hasColumn(std::string_view name) const {
  for (const auto& n : names_)
    if (n == name) return true;
  return false;
}

std::size_t Table::columnIndex(std::string_view name) const {
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return i;
  std::string available;
  for (const auto& n : names_) available += (available.empty() ? "" : ", ") + n;
  throw AnalysisError(source_ + ": no column '" + std::string(name) + "' (columns: " + available + ")");
}

const std::string& Table::text(std::size_t row, std::size_t column) const {
  return columns_.at(column).at(row);
}

double Table::number(std::size_t row, std::size_t column) const {
  double value = 0.0;
  const std::string& cell = text(row, column);
  if (!parseDouble(cell, value))
    throw AnalysisError(where(row) + ": column '" + names_[column] + "': '" + cell +
                        "' is not a number");
  return value;
}

std::vector<double> Table::numericColumn(std::string_view name) const {
  const std::size_t c = columnIndex(name);
  std::vector<double> values(rowCount());
  for (std::size_t r = 0; r < rowCount(); ++r) values[r] = number(r, c);
  return values;
}

std::vector<std::string> Table::textColumn(std::string_view name) const {
  return columns_[columnIndex(name)];
}

std::string Table::where(std::size_t row) const {
  return source_ + ":" + std::to_string(origins_.at(row));
}

Table Table::rowsWhere(std::string_view column, std::string_view value) const {
  const std::size_t c = columnIndex(column);
  Table subset(source_, names_);
  for (std::size_t r = 0; r < rowCount(); ++r) {
    if (columns_[c][r] != value) continue;
    std::vector<std::string> cells;
    for (const auto& col : columns_) cells.push_back(col[r]);
    subset.addRow(std::move(cells), origins_[r]);
  }
  return subset;
}

}  // namespace tlab::analysis
