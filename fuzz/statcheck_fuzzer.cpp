// Fuzz target: free text → statcheck report (RE2 scanner, p recomputation, verdicts), with
// statcheck's options taken from the first byte; the same text as HTML (libxml2) and through the
// PDF typesetting fixes. Any text is valid input, so nothing may throw (except the HTML reader's
// one-line AnalysisError for a document libxml2 cannot recover).
// fuzz-sources: analysis/statcheck.cpp analysis/statcheck_scanner.cpp analysis/document_text.cpp
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "analysis/analysis_error.hpp"
#include "analysis/document_text.hpp"
#include "analysis/statcheck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tlab::analysis::StatcheckOptions options;
  const unsigned bits = size > 0 ? data[0] : 0u;
  options.pEqualAlphaSignificant = (bits & 1u) == 0;
  options.pZeroError = (bits & 2u) == 0;
  options.oneTailedTests = (bits & 4u) != 0;
  options.oneTailedText = (bits & 8u) != 0;
  tlab::analysis::statcheck(text, "fuzz.txt", options);
  tlab::analysis::statcheck(tlab::analysis::fixPdfTypesetting(text), "fuzz.pdf", options);
  try {
    tlab::analysis::statcheck(tlab::analysis::htmlText(text, "fuzz.html"), "fuzz.html", options);
  } catch (const tlab::analysis::AnalysisError&) {  // "not readable as HTML" is a valid answer
  }
  return 0;
}
