#include "analysis/result_json.hpp"

#include <cmath>

namespace tlab::analysis {

namespace {

nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }
nlohmann::json interval(const Interval& i) { return {number(i.lo), number(i.hi)}; }
nlohmann::json reported(const ReportedValue& v) { return v.text; }

}  // namespace

nlohmann::json toJson(const TTestResult& r) {
  return {{"test", std::string(tTestKindName(r.kind))},
          {"t", number(r.t)},
          {"df", number(r.df)},
          {"p", number(r.p)},
          {"mean_diff", number(r.meanDiff)},
          {"ci_low", number(r.ciLow)},
          {"ci_high", number(r.ciHigh)},
          {"d", number(r.cohensD)},
          {"hedges_g", number(r.hedgesG)},
          {"se", number(r.se)},
          {"alternative", std::string(alternativeName(r.alternative))},
          {"conf_level", number(r.confidence)}};
}

nlohmann::json toJson(const AnovaResult& r) {
  nlohmann::json effects = nlohmann::json::array();
  for (const auto& e : r.effects) {
    nlohmann::json j = {{"effect", e.name},       {"F", number(e.F)},
                        {"df1", number(e.df1)},    {"df2", number(e.df2)},
                        {"p", number(e.p)},        {"eta2_partial", number(e.eta2Partial)},
                        {"eta2_generalized", number(e.eta2Generalized)},
                        {"ss", number(e.ss)},      {"ss_error", number(e.ssError)},
                        {"within", e.withinSubjects}};
    if (e.sphericity) {
      j["eps_gg"] = number(e.sphericity->epsilonGG);
      j["eps_hf"] = number(e.sphericity->epsilonHF);
      j["p_gg"] = number(e.pGG);
      j["p_hf"] = number(e.pHF);
      j["mauchly_w"] = number(e.sphericity->mauchlyW);
      j["mauchly_p"] = number(e.sphericity->mauchlyP);
    }
    effects.push_back(j);
  }
  return {{"effects", effects},
          {"ss_type", std::string(sumOfSquaresTypeName(r.ssType))},
          {"subjects", r.subjects},
          {"replicates_averaged", r.maxReplicates}};
}

nlohmann::json toJson(const FriedmanResult& r) {
  return {{"chisq", number(r.chiSquared)}, {"df", number(r.df)}, {"p", number(r.p)},
          {"subjects", r.blocks},           {"conditions", r.treatments}};
}

nlohmann::json toJson(const WilcoxonSignedRankResult& r) {
  return {{"V", number(r.V)}, {"p", number(r.p)}, {"exact", r.exact}, {"n", r.n}, {"zeros", r.zeros},
          {"ties", r.ties},   {"alternative", std::string(alternativeName(r.alternative))}};
}

nlohmann::json toJson(const MannWhitneyResult& r) {
  return {{"W", number(r.W)}, {"p", number(r.p)}, {"exact", r.exact}, {"ties", r.ties},
          {"n_x", r.nx},      {"n_y", r.ny},      {"alternative", std::string(alternativeName(r.alternative))}};
}

nlohmann::json toJson(const Descriptives& d) {
  return {{"n", d.n},          {"mean", number(d.mean)},     {"sd", number(d.sd)},
          {"var", number(d.variance)}, {"se", number(d.se)}, {"ci_low", number(d.ciLow)},
          {"ci_high", number(d.ciHigh)}, {"min", number(d.min)}, {"q1", number(d.q1)},
          {"median", number(d.median)}, {"q3", number(d.q3)}, {"max", number(d.max)}};
}

nlohmann::json toJson(const TTestHypothesisCheck& h) {
  nlohmann::json j = {{"test", std::string(tTestKindName(h.kind))},
                      {"t", number(h.t)},
                      {"df", number(h.df)},
                      {"p_one_sided", number(h.pOneSided)},
                      {"abs_t_range", interval(h.absTRange)},
                      {"df_range", interval(h.dfRange)},
                      {"p_range", interval(h.pRange)},
                      {"df_consistent", h.dfConsistent},
                      {"t_consistent", h.tConsistent},
                      {"p_consistent", h.pConsistent},
                      {"consistent", h.consistent()}};
  if (h.kind == TTestKind::Paired) {
    j["implied_r"] = number(h.impliedCorrelation);
    j["implied_r_range"] = interval(h.impliedCorrelationRange);
  }
  return j;
}

nlohmann::json toJson(const std::vector<TableComparison>& rows) {
  nlohmann::json out = nlohmann::json::array();
  const auto printed = [](const std::optional<ReportedValue>& v) { return v ? nlohmann::json(v->text) : nlohmann::json(nullptr); };
  for (const auto& row : rows) {
    const PrintedTTest& p = row.printed;
    nlohmann::json checks = nlohmann::json::array();
    std::vector<std::string> consistentWith;
    for (const auto& h : row.checks) {
      checks.push_back(toJson(h));
      if (h.consistent()) consistentWith.emplace_back(tTestKindName(h.kind));
    }
    out.push_back({{"comparison", row.first + " vs " + row.second},
                   {"where", row.where},
                   {"published",
                    {{"mean1", p.mean1.text}, {"mean2", p.mean2.text}, {"var1", number(p.variance1)},
                     {"var2", number(p.variance2)}, {"n1", p.n1}, {"n2", p.n2}, {"df", printed(p.df)},
                     {"t", printed(p.t)}, {"p", printed(p.p)}, {"p_tails", p.pTails}}},
                   {"checks", checks},
                   {"consistent_with", consistentWith}});
  }
  return {{"rows", out}};
}

nlohmann::json toJson(const CarneckyReproduction& r) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : r.rows) {
    const auto& c = row.published;
    nlohmann::json checks = nlohmann::json::array();
    for (const auto& h : row.checks) checks.push_back(toJson(h));
    rows.push_back({{"comparison", c.first + " vs " + c.second},
                    {"published",
                     {{"mean1", reported(c.mean1)},
                      {"var1", reported(c.variance1)},
                      {"mean2", reported(c.mean2)},
                      {"var2", reported(c.variance2)},
                      {"n", c.n},
                      {"df", reported(c.df)},
                      {"t", reported(c.t)},
                      {"p_one_sided", reported(c.pOneSided)},
                      {"p_in_text", reported(c.pInText)}}},
                    {"checks", checks},
                    {"sign_matches_means", row.signMatchesMeans},
                    {"p_two_sided_welch", number(row.pTwoSidedWelch)},
                    {"text_p_is_two_sided", row.textPIsTwoSided},
                    {"text_p_is_one_sided", row.textPIsOneSided}});
  }
  return {{"paper", "Carnecky et al. 2013, Table 1"}, {"rows", rows}, {"findings", r.findings}};
}

nlohmann::json toJson(const ElmqvistReproduction& r) {
  nlohmann::json tests = nlohmann::json::array();
  for (const auto& c : r.fTests) {
    const auto& t = c.published;
    tests.push_back({{"measure", t.measure},
                     {"location", t.location},
                     {"mean_inactive", reported(t.meanInactive)},
                     {"sd_inactive", reported(t.sdInactive)},
                     {"mean_active", reported(t.meanActive)},
                     {"sd_active", reported(t.sdActive)},
                     {"F", reported(t.F)},
                     {"df1", c.df1},
                     {"df2", c.df2},
                     {"p_reported", std::string(pRelationSymbol(t.pRelation)) + " " + t.p.text},
                     {"p_computed", number(c.pComputed)},
                     {"p_range", interval(c.pRange)},
                     {"p_consistent", c.pConsistent},
                     {"implied_r", number(c.impliedCorrelation)},
                     {"implied_r_range", interval(c.impliedCorrelationRange)},
                     {"r_possible", c.correlationPossible}});
  }
  return {{"paper", "Elmqvist, Assarsson & Tsigas, Sec. VII"},
          {"f_tests", tests},
          {"design_count", r.designCount},
          {"reported_task_count", r.reportedTaskCount},
          {"tasks_per_scenario", r.tasksPerScenario},
          {"findings", r.findings}};
}

nlohmann::json toJson(const StatcheckReport& r) {
  // statcheck's fields (R/constants.R) under its names, then tlab's.
  nlohmann::json results = nlohmann::json::array();
  for (const auto& v : r.verdicts) {
    const auto& a = v.result;
    const bool ns = a.pRelation == PRelation::NotSignificant;
    results.push_back({{"raw", a.text},
                       {"test_type", std::string(statisticName(a.kind))},
                       {"df1", number(a.df1)},
                       {"df2", number(a.df2)},
                       {"test_comp", std::string(comparisonSymbol(a.testComparison))},
                       {"test_value", number(a.statistic.value)},
                       {"test_decimals", a.statistic.decimals},
                       {"p_comp", std::string(pRelationSymbol(a.pRelation))},
                       {"reported_p", ns ? nlohmann::json(nullptr) : number(a.p.value)},
                       {"p_decimals", ns ? nlohmann::json(nullptr) : nlohmann::json(a.p.decimals)},
                       {"computed_p", number(v.pComputed)},
                       {"computed_p_range", interval(v.pRange)},
                       {"one_tailed", v.oneTailed},
                       {"error", !v.consistent},
                       {"decision_error", v.decisionError},
                       {"consistent_if_one_tailed", v.consistentIfOneTailed},
                       {"line", a.line},
                       {"note", v.note}});
  }
  nlohmann::json pValues = nlohmann::json::array();
  for (const auto& p : r.pValues) {
    const bool ns = p.relation == PRelation::NotSignificant;
    pValues.push_back({{"p_comp", std::string(pRelationSymbol(p.relation))},
                       {"reported_p", ns ? nlohmann::json(nullptr) : number(p.p.value)},
                       {"p_decimals", ns ? nlohmann::json(nullptr) : nlohmann::json(p.p.decimals)},
                       {"line", p.line}});
  }
  const double apa = r.apaFactor();
  return {{"source", r.source},
          {"results", results},
          {"p_values", pValues},
          {"summary",
           {{"results", r.verdicts.size()},
            {"errors", r.inconsistencies()},
            {"decision_errors", r.decisionErrors()},
            {"p_values", r.pValues.size()},
            {"p_values_without_statistic", r.pValuesWithoutStatistic()},
            {"apa_factor", std::isfinite(apa) ? nlohmann::json(std::round(apa * 100.0) / 100.0) : nlohmann::json(nullptr)},
            {"one_tailed_in_txt", r.oneTailedInText}}}};
}

nlohmann::json toJson(const PairwiseResult& r) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : r.rows) {
    nlohmann::json j = {{"first", row.first},         {"second", row.second},         {"test", row.test},
                        {"t", number(row.t)},         {"df", number(row.df)},         {"mean_diff", number(row.meanDiff)},
                        {"p", number(row.p)},         {"p_adjusted", number(row.pAdjusted)}};
    if (!row.error.empty()) j["error"] = row.error;
    rows.push_back(j);
  }
  return {{"factor", r.factor}, {"adjust", std::string(pAdjustName(r.adjust))}, {"comparisons", rows}};
}

}  // namespace tlab::analysis
