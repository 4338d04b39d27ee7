#include "analysis/row_filter.hpp"

#include <algorithm>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// The rows of `table` for which keep(row) holds.
template <class Keep>
Table rowsIf(const Table& table, Keep keep) {
  Table subset(table.source(), table.columnNames());
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    if (!keep(r)) continue;
    std::vector<std::string> cells;
    cells.reserve(table.columnCount());
    for (std::size_t c = 0; c < table.columnCount(); ++c) cells.push_back(table.text(r, c));
    subset.addRow(std::move(cells), table.origin(r));
  }
  return subset;
}

}  // namespace

RowFilter parseRowFilter(std::string_view text) {
  const auto equals = text.find('=');
  const std::string_view column = equals == std::string_view::npos ? text : trimmed(text.substr(0, equals));
  if (equals == std::string_view::npos || column.empty())
    throw AnalysisError("--where '" + std::string(text) + "': expected COLUMN=VALUE[,VALUE...]");
  RowFilter filter{std::string(column), {}};
  std::string_view rest = text.substr(equals + 1);
  for (;;) {
    const auto comma = rest.find(',');
    const std::string_view value = trimmed(rest.substr(0, comma));
    if (!value.empty()) filter.values.emplace_back(value);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  if (filter.values.empty()) throw AnalysisError("--where '" + std::string(text) + "': no value after '='");
  return filter;
}

Table rowsMatching(const Table& table, const std::vector<RowFilter>& filters) {
  std::vector<std::size_t> columns;
  for (const auto& f : filters) columns.push_back(table.columnIndex(f.column));
  return rowsIf(table, [&](std::size_t r) {
    for (std::size_t i = 0; i < filters.size(); ++i) {
      const auto& values = filters[i].values;
      if (std::find(values.begin(), values.end(), table.text(r, columns[i])) == values.end()) return false;
    }
    return true;
  });
}

bool isMissingCell(std::string_view cell) {
  cell = trimmed(cell);
  return cell.empty() || cell == "NA";
}

WithoutMissing dropMissing(const Table& table, std::string_view column) {
  const std::size_t c = table.columnIndex(column);
  WithoutMissing result{rowsIf(table, [&](std::size_t r) { return !isMissingCell(table.text(r, c)); }), 0};
  result.dropped = table.rowCount() - result.table.rowCount();
  return result;
}

}  // namespace tlab::analysis
