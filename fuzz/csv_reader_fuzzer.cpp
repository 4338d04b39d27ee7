// Fuzz target: CSV text → Table (the reader behind `tlab stats`). Rejections must be
// AnalysisError naming file:line.
// fuzz-sources: analysis/csv_reader.cpp
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "analysis/analysis_error.hpp"
#include "analysis/csv_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    tlab::analysis::parseCsv(text, "fuzz.csv");
  } catch (const tlab::analysis::AnalysisError&) {
  }
  return 0;
}
