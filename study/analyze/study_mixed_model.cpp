#include "study/analyze/study_mixed_model.hpp"

#include <algorithm>
#include <set>

#include "analysis/mixed_model_report.hpp"
#include "analysis/model_formula.hpp"

namespace tlab::study {

namespace {

std::size_t distinctValues(const analysis::Table& table, const std::string& column) {
  const auto values = table.textColumn(column);
  return std::set<std::string>(values.begin(), values.end()).size();
}

}  // namespace

analysis::MixedFamily mixedModelFamily(const std::string& dv) {
  return dv == "correct" || dv == "answered" ? analysis::MixedFamily::Binomial : analysis::MixedFamily::Gaussian;
}

std::string mixedModelFormula(const analysis::Table& table, const AnalysisSpec& spec, const std::string& dv) {
  if (!spec.formula.empty() && analysis::parseModelFormula(spec.formula).response == dv) return spec.formula;
  std::string fixed;
  for (const auto& list : {spec.between, spec.within})
    for (const auto& factor : list)
      if (distinctValues(table, factor) > 1) fixed += (fixed.empty() ? "" : " * ") + factor;
  std::string formula = (dv == "rt" ? "log(rt)" : dv) + " ~ " + (fixed.empty() ? "1" : fixed) + " + (1 | participant)";
  if (distinctValues(table, "stimulus") > 1) formula += " + (1 | stimulus)";
  return formula;
}

analysis::MixedModelResult fitStudyMixedModel(const analysis::Table& table, const Experiment& e, const AnalysisSpec& spec,
                                              const std::string& dv) {
  analysis::MixedModelRequest request;
  request.formula = mixedModelFormula(table, spec, dv);
  request.family = mixedModelFamily(dv);
  for (const auto& factor : e.factors) {
    request.variables.factors.insert(factor.name);
    auto& levels = request.variables.levels[factor.name];
    for (const auto& level : factor.levels) levels.push_back(level.name);
  }
  return analysis::fitMixedModel(table, request);
}

analysis::ReportSection mixedModelSection(const std::string& label, const analysis::MixedModelResult& r) {
  analysis::ReportSection s;
  s.heading = label + ": mixed model";
  std::string text = "Model: " + r.description() + ".";
  if (r.formula.find("stimulus") != std::string::npos) text += " The stimulus is the image shown (its SHA-256).";
  s.paragraphs = {text, analysis::fitSummaryLine(r) + "."};
  for (const auto& w : r.warnings) s.warnings.push_back("Warning (" + label + "): " + w);
  s.tables = {analysis::fixedEffectsTable(r), analysis::randomEffectsTable(r)};
  return s;
}

}  // namespace tlab::study
