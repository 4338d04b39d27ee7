#pragma once
// JSON forms of the analysis results, with the field names of the `tlab stats` interface
// (issue 3): numbers are doubles at full precision (nlohmann::json prints the shortest
// round-trip representation); NaN and ±inf become null.
#include <nlohmann/json.hpp>

#include "analysis/anova.hpp"
#include "analysis/descriptives.hpp"
#include "analysis/pairwise_tests.hpp"
#include "analysis/rank_tests.hpp"
#include "analysis/reproduce_carnecky.hpp"
#include "analysis/reproduce_elmqvist.hpp"
#include "analysis/reproduce_table.hpp"
#include "analysis/statcheck.hpp"
#include "analysis/ttest.hpp"

namespace tlab::analysis {

// {"test","t","df","p","mean_diff","ci_low","ci_high","d"} plus "hedges_g", "se",
// "alternative", "conf_level".
nlohmann::json toJson(const TTestResult& r);
// {"effects":[{"effect","F","df1","df2","p","eps_gg","eps_hf","p_gg","p_hf","mauchly_w","mauchly_p",
//   "eta2_partial","eta2_generalized"}]} (sphericity fields only for within effects with > 2
// levels) plus "ss", "ss_error", "ss_type", "subjects", "replicates_averaged".
nlohmann::json toJson(const AnovaResult& r);
nlohmann::json toJson(const FriedmanResult& r);             // {"chisq","df","p"}
nlohmann::json toJson(const WilcoxonSignedRankResult& r);   // {"V","p"} plus "exact","n","zeros"
nlohmann::json toJson(const MannWhitneyResult& r);          // {"W","p"} plus "exact"
nlohmann::json toJson(const Descriptives& d);
nlohmann::json toJson(const TTestHypothesisCheck& h);
nlohmann::json toJson(const CarneckyReproduction& r);
// {"rows":[{"comparison","where","published","checks","consistent_with"}]}
nlohmann::json toJson(const std::vector<TableComparison>& rows);
nlohmann::json toJson(const ElmqvistReproduction& r);
nlohmann::json toJson(const StatcheckReport& r);
// {"factor","adjust","comparisons":[{"first","second","test","t","df","mean_diff","p","p_adjusted","error"?}]}
nlohmann::json toJson(const PairwiseResult& r);

}  // namespace tlab::analysis
