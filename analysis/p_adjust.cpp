#include "analysis/p_adjust.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numeric>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

// R's order(p) (stable) or order(p, decreasing = TRUE) (stable too: ties keep their order).
std::vector<std::size_t> order(const std::vector<double>& p, bool decreasing) {
  std::vector<std::size_t> o(p.size());
  std::iota(o.begin(), o.end(), std::size_t{0});
  std::stable_sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return decreasing ? p[a] > p[b] : p[a] < p[b]; });
  return o;
}

// The step-up/step-down methods of p.adjust on the non-missing p-values:
//   holm:     pmin(1, cummax((n - i + 1) · p[o]))[ro],   i = 1..n, o = order(p)
//   hochberg: pmin(1, cummin((n + 1 - i) · p[o]))[ro],   i = n..1, o = order(p, decreasing = TRUE)
//   BH:       pmin(1, cummin(n / i · p[o]))[ro]
//   BY:       pmin(1, cummin(q · n / i · p[o]))[ro],     q = Σ_{k=1}^{n} 1/k
std::vector<double> adjustComplete(const std::vector<double>& p, PAdjustMethod method) {
  const std::size_t n = p.size();
  const double nd = static_cast<double>(n);
  std::vector<double> out(n);
  if (method == PAdjustMethod::None) return p;
  if (method == PAdjustMethod::Bonferroni) {
    for (std::size_t k = 0; k < n; ++k) out[k] = std::min(1.0, nd * p[k]);
    return out;
  }
  if (method == PAdjustMethod::Holm) {
    const auto o = order(p, false);
    double running = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double i = static_cast<double>(k + 1);
      running = std::max(running, (nd - i + 1.0) * p[o[k]]);
      out[o[k]] = std::min(1.0, running);
    }
    return out;
  }
  double q = 1.0;
  if (method == PAdjustMethod::BY) {
    q = 0.0;
    for (std::size_t k = 1; k <= n; ++k) q += 1.0 / static_cast<double>(k);
  }
  const auto o = order(p, true);
  double running = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) {
    const double i = nd - static_cast<double>(k);  // i = n, n-1, ..., 1
    const double factor = method == PAdjustMethod::Hochberg ? (nd + 1.0 - i) : q * nd / i;
    running = std::min(running, factor * p[o[k]]);
    out[o[k]] = std::min(1.0, running);
  }
  return out;
}

}  // namespace

std::string_view pAdjustName(PAdjustMethod method) {
  switch (method) {
    case PAdjustMethod::None: return "none";
    case PAdjustMethod::Bonferroni: return "bonferroni";
    case PAdjustMethod::Holm: return "holm";
    case PAdjustMethod::Hochberg: return "hochberg";
    case PAdjustMethod::BH: return "BH";
    case PAdjustMethod::BY: return "BY";
  }
  return "none";
}

PAdjustMethod parsePAdjustMethod(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "none") return PAdjustMethod::None;
  if (lower == "bonferroni") return PAdjustMethod::Bonferroni;
  if (lower == "holm") return PAdjustMethod::Holm;
  if (lower == "hochberg") return PAdjustMethod::Hochberg;
  if (lower == "bh" || lower == "fdr") return PAdjustMethod::BH;
  if (lower == "by") return PAdjustMethod::BY;
  throw AnalysisError("'" + std::string(text) + "' is not a p-value adjustment: use holm, bonferroni, hochberg, BH, BY or none");
}

std::vector<double> pAdjust(const std::vector<double>& p, PAdjustMethod method) {
  std::vector<double> present;
  for (const double x : p)
    if (!std::isnan(x)) present.push_back(x);
  const std::vector<double> adjusted = adjustComplete(present, method);
  std::vector<double> out(p.size(), std::nan(""));
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::isnan(p[i])) out[i] = adjusted[k++];
  return out;
}

}  // namespace tlab::analysis
