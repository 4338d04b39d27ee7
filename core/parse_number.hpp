#pragma once
// Whole-string parsing of a finite number, shared by every parser of user-given values
// (scene parameters, style parameters, camera fields), and the text that reads back as the same
// number. Callers word their own error messages.
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

// v as printf's %g with the fewest significant digits, at least 6, that read back as v: what
// `std::ostream << v` writes wherever that is exact (0.25, 1e-06, 100000), and every digit a
// value needs beyond that (0.1234567, not 0.123457), so that a default or a range end printed in
// a message or stored as text is the number that was declared.
inline std::string roundTripText(double v) {
  char buffer[32];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    if (!std::isfinite(v) || std::strtod(buffer, nullptr) == v) break;
  }
  return buffer;
}

}  // namespace tlab::core
