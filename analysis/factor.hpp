#pragma once
// Factor: a categorical column of a Table, as the sorted list of its levels plus the level of each
// row. Levels are ordered like R's factor(): numerically when every label is a number
// ("2" < "10"), otherwise by byte value (the C locale). This fixes which group is "x" in a
// two-sample test: the first level, as in R's t.test(dv ~ group).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/table.hpp"

namespace tlab::analysis {

struct Factor {
  std::string name;
  std::vector<std::string> levels;
  std::vector<std::size_t> codes;  // codes[row] indexes levels
};

Factor makeFactor(const Table& table, std::string_view column);

// Throws AnalysisError unless the factor has between minLevels and maxLevels levels
// (e.g. "factor 'group' has only one level ('a'): a factor needs at least 2 levels").
void requireLevelCount(const Factor& factor, std::size_t minLevels, std::size_t maxLevels,
                       std::string_view purpose);

}  // namespace tlab::analysis
