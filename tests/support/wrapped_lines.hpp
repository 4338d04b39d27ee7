#pragma once
// Word-wrapped lines joined again with single spaces: equal to the text they came from when the
// wrapping kept every word, in order (window header and answer band tests).
#include <string>
#include <vector>

namespace tlab::testing {

inline std::string joinedWithSpaces(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += (s.empty() ? "" : " ") + l;
  return s;
}

}  // namespace tlab::testing
