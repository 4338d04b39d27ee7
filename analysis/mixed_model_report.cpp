#include "analysis/mixed_model_report.hpp"

#include <cmath>

#include "analysis/number_format.hpp"

namespace tlab::analysis {

namespace {

nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json toJson(const MixedModelResult& r) {
  const bool gaussian = r.family == MixedFamily::Gaussian;
  nlohmann::json fixed = nlohmann::json::array(), random = nlohmann::json::array(), groups = nlohmann::json::object();
  for (const auto& e : r.fixedEffects) {
    nlohmann::json j = {{"term", e.term}, {"estimate", number(e.estimate)}, {"std_error", number(e.stdError)},
                        {"statistic", number(e.statistic)}, {"p", number(e.p)}};
    if (gaussian) j["df"] = number(e.df);
    fixed.push_back(j);
  }
  for (const auto& v : r.randomEffects) {
    nlohmann::json j = {{"group", v.group}, {"term", v.term}, {"variance", number(v.variance)}, {"sd", number(v.sd)}};
    if (!v.term2.empty()) j["term2"] = v.term2, j["correlation"] = number(v.correlation);
    random.push_back(j);
  }
  for (const auto& [g, levels] : r.groups) groups[g] = levels;
  nlohmann::json j = {{"model", r.description()},
                      {"formula", r.formula},
                      {"family", std::string(mixedFamilyName(r.family))},
                      {"method", gaussian ? (r.reml ? "REML" : "ML") : "Laplace"},
                      {"observations", r.observations},
                      {"groups", groups},
                      {"fixed_effects", fixed},
                      {"random_effects", random},
                      {"log_likelihood", number(r.logLikelihood)},
                      {"aic", number(r.aic)},
                      {"deviance", number(r.deviance)},
                      {"theta", std::vector<double>(r.theta.data(), r.theta.data() + r.theta.size())},
                      {"evaluations", r.evaluations},
                      {"singular", r.singular},
                      {"converged", r.converged},
                      {"warnings", r.warnings}};
  if (gaussian) j["sigma"] = number(r.sigma);
  if (r.reml) j["reml_criterion"] = number(r.remlCriterion);
  return j;
}

TextTable fixedEffectsTable(const MixedModelResult& r) {
  const bool gaussian = r.family == MixedFamily::Gaussian;
  TextTable t;
  t.caption = "Fixed effects";
  t.header = gaussian ? std::vector<std::string>{"term", "estimate", "SE", "df", "t", "p"}
                      : std::vector<std::string>{"term", "estimate", "SE", "z", "p"};
  for (const auto& e : r.fixedEffects) {
    std::vector<std::string> row = {e.term, formatNumber(e.estimate, 6), formatNumber(e.stdError, 6)};
    if (gaussian) row.push_back(formatNumber(e.df, 6));
    row.push_back(formatNumber(e.statistic, 5));
    row.push_back(formatP(e.p));
    t.rows.push_back(std::move(row));
  }
  return t;
}

TextTable randomEffectsTable(const MixedModelResult& r) {
  TextTable t;
  t.caption = "Random effects (variance components)";
  t.header = {"group", "term", "variance", "SD", "correlation"};
  for (const auto& v : r.randomEffects) {
    if (!v.term2.empty()) {
      t.rows.push_back({v.group, v.term + " ~ " + v.term2, "", "", formatNumber(v.correlation, 4)});
      continue;
    }
    t.rows.push_back({v.group, v.term, formatNumber(v.variance, 6), formatNumber(v.sd, 6), ""});
  }
  return t;
}

std::string fitSummaryLine(const MixedModelResult& r) {
  std::string s = r.reml ? "REML criterion " + formatNumber(r.remlCriterion, 7) + ", REML log-likelihood "
                         : "log-likelihood ";
  s += formatNumber(r.logLikelihood, 7) + ", AIC " + formatNumber(r.aic, 7) + "; " + std::to_string(r.observations) + " observations";
  for (const auto& [g, levels] : r.groups) s += "; " + g + ": " + std::to_string(levels) + " levels";
  return s;
}

}  // namespace tlab::analysis
