#pragma once
// The statcheck scanner: finds APA-style results, p-values and one-tailed wording in text.
// Patterns run on RE2 (linear time in the input whatever it holds, no backtracking), on the text
// after normalization (Unicode minus/dashes, χ, ², ≤ ≥, no-break and thin spaces, line breaks).
// The grammar is statcheck's (R/regex.R) with the differences README.md lists.
#include <string>
#include <string_view>
#include <vector>

#include "analysis/statcheck.hpp"

namespace tlab::analysis {

// Text with extraction variants mapped to ASCII, and where each source line starts in it.
struct NormalizedText {
  std::string text;
  std::vector<std::size_t> lineStarts;  // offsets in `text`; line 1 starts at 0
  std::size_t lineAt(std::size_t offset) const;  // 1-based source line of a byte of `text`
};
NormalizedText normalizeForStatcheck(std::string_view in);

// Results in reading order. Skipped like any other text (as statcheck does): p > 1, |r| > 1, a
// non-positive or non-finite df, a value beyond double's range.
std::vector<ApaResult> extractApaResults(std::string_view text);
std::vector<ApaResult> extractApaResults(const NormalizedText& text);
std::vector<ReportedP> extractPValues(std::string_view text);
std::vector<ReportedP> extractPValues(const NormalizedText& text);
// "one-sided", "one-tailed" (any one character or none between) or "directional", any case.
bool mentionsOneTailed(std::string_view text);

}  // namespace tlab::analysis
