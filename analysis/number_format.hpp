#pragma once
// Number formatting for human-readable output (text tables, HTML, Markdown). Machine-readable
// output (JSON) never goes through here: it keeps full double precision.
#include <string>

namespace tlab::analysis {

// `significant` significant digits, no exponent for ordinary magnitudes; "NA" for NaN, "inf".
std::string formatNumber(double x, int significant = 4);
// p-values APA-like: ".0123", "< .001" only when asked; here: 3 decimals, or 3 significant
// digits in scientific notation below .001 (so 1e-300 stays visible).
std::string formatP(double p);
// Minimal HTML escaping of text (&, <, >, ").
std::string escapeHtml(const std::string& text);
// Standard base64 (RFC 4648) for data: URIs.
std::string base64Encode(const std::string& bytes);

}  // namespace tlab::analysis
