#pragma once
// Reader for long-format CSV files (RFC 4180): a header row naming the columns, one record per
// line, fields separated by commas, fields optionally enclosed in double quotes (which may then
// contain commas, line breaks and doubled quotes ""), LF or CRLF line ends, an optional UTF-8 BOM.
// Errors name file:line.
#include <string>
#include <string_view>

#include "analysis/table.hpp"

namespace tlab::analysis {

// Reads a CSV file into a Table; throws AnalysisError ("file:line: ...") on malformed input.
Table readCsvFile(const std::string& path);
// Parses CSV text; `source` names it in messages.
Table parseCsv(std::string_view text, const std::string& source);

}  // namespace tlab::analysis
