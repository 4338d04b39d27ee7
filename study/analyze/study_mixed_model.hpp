#pragma once
// The mixed model of tests = ["mixed"] in an [[analysis]]: for one dependent variable (of one
// task), its lme4 formula — the analysis's `formula` when it names this variable, otherwise
//   correct ~ F1 * F2 + (1 | participant) + (1 | stimulus)   binomial GLMM (logit, Laplace)
//   log(rt) ~ F1 * F2 + (1 | participant) + (1 | stimulus)   linear mixed model, REML
//   score ~ ...                                              linear mixed model, REML
// with the analysis's factors that vary in the data as fixed effects (levels in the experiment's
// order, the first the reference) and the stimulus as the image's sha256 — and the report section
// that names the model as a methods section would.
#include <string>

#include "analysis/mixed_model.hpp"
#include "analysis/report.hpp"
#include "analysis/table.hpp"
#include "study/design/experiment.hpp"

namespace tlab::study {

analysis::MixedFamily mixedModelFamily(const std::string& dv);  // binomial for correct and answered
std::string mixedModelFormula(const analysis::Table& table, const AnalysisSpec& spec, const std::string& dv);
analysis::MixedModelResult fitStudyMixedModel(const analysis::Table& table, const Experiment& e, const AnalysisSpec& spec,
                                              const std::string& dv);
analysis::ReportSection mixedModelSection(const std::string& label, const analysis::MixedModelResult& r);

}  // namespace tlab::study
