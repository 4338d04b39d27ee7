#include "analysis/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace tlab::analysis {

std::string formatNumber(double x, int significant) {
  if (std::isnan(x)) return "NA";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[64];
  const double magnitude = std::fabs(x);
  if (magnitude != 0.0 && (magnitude < 1e-4 || magnitude >= 1e9))
    std::snprintf(buffer, sizeof buffer, "%.*e", significant - 1, x);
  else
    std::snprintf(buffer, sizeof buffer, "%.*g", significant, x);
  return buffer;
}

std::string formatP(double p) {
  if (std::isnan(p)) return "NA";
  char buffer[64];
  if (p < 0.001)
    std::snprintf(buffer, sizeof buffer, "%.3g", p);
  else
    std::snprintf(buffer, sizeof buffer, "%.4f", p);
  return buffer;
}

std::string escapeHtml(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out.push_back(c);
    }
  }
  return out;
}

std::string base64Encode(const std::string& bytes) {
  static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto b0 = static_cast<unsigned char>(bytes[i]);
    const auto b1 = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0u;
    const auto b2 = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0u;
    const unsigned triple = (b0 << 16) | (b1 << 8) | b2;
    out.push_back(alphabet[(triple >> 18) & 63]);
    out.push_back(alphabet[(triple >> 12) & 63]);
    out.push_back(i + 1 < bytes.size() ? alphabet[(triple >> 6) & 63] : '=');
    out.push_back(i + 2 < bytes.size() ? alphabet[triple & 63] : '=');
  }
  return out;
}

}  // namespace tlab::analysis
