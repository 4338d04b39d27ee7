#pragma once
// Whole-string parsing of a finite number, shared by every parser of user-given values
// (scene parameters, style parameters, camera fields). Callers word their own error messages.
#include <cmath>
#include <optional>
#include <string>

namespace tlab::core {

inline std::optional<double> parseFiniteNumber(const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (text.empty() || used != text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace tlab::core
