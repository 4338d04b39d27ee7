#pragma once
// The forms of a mixed-model fit shown to people and programs: the JSON of `tlab stats mixed
// --json` (fixed_effects, random_effects, log_likelihood, aic, reml_criterion, warnings, ...) and
// the tables of the terminal and of the study report.
#include <nlohmann/json.hpp>

#include "analysis/mixed_model.hpp"
#include "analysis/text_table.hpp"

namespace tlab::analysis {

// {"model","formula","family","method","observations","groups":{g: levels},
//  "fixed_effects":[{"term","estimate","std_error","statistic","df"?,"p"}],
//  "random_effects":[{"group","term","term2"?,"variance","sd","correlation"?}],
//  "sigma"?,"log_likelihood","aic","deviance","reml_criterion"?,"theta","singular","converged","warnings"}
// A correlation row carries term2, the covariance as "variance", "sd": null and "correlation".
nlohmann::json toJson(const MixedModelResult& r);

TextTable fixedEffectsTable(const MixedModelResult& r);
TextTable randomEffectsTable(const MixedModelResult& r);
// "REML criterion 123.4, log-likelihood −61.7, AIC 133.4; 240 observations; participant 12, stimulus 20"
std::string fitSummaryLine(const MixedModelResult& r);

}  // namespace tlab::analysis
