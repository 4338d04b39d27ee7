#pragma once
// Row filters of `tlab stats`: keep the rows whose column holds one of the listed values
// (`--where phase=test --where task=layer-index,nearest-point`), and drop the rows whose
// dependent variable is missing — an empty cell or R's "NA" — as R's na.omit() would, counting
// them so the caller can say how many went.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/table.hpp"

namespace tlab::analysis {

struct RowFilter {
  std::string column;
  std::vector<std::string> values;  // a row is kept when its cell equals one of these
};

// "COLUMN=V1,V2" → {COLUMN, {V1, V2}}; throws AnalysisError naming the text when it has no
// column, no '=' or no value.
RowFilter parseRowFilter(std::string_view text);

// The rows that pass every filter (same columns, same origins); a filter's column must exist.
Table rowsMatching(const Table& table, const std::vector<RowFilter>& filters);

// A cell that stands for a missing value: empty (blanks only) or "NA".
bool isMissingCell(std::string_view cell);

struct WithoutMissing {
  Table table;
  std::size_t dropped = 0;  // rows whose cell in the column was missing
};

// The rows whose cell in `column` is not missing.
WithoutMissing dropMissing(const Table& table, std::string_view column);

}  // namespace tlab::analysis
