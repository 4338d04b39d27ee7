#pragma once
// Adjustment of p-values for multiple comparisons, exactly as R's stats::p.adjust (R 4.2,
// src/library/stats/R/p.adjust.R): Bonferroni, Holm (1979), Hochberg (1988), Benjamini &
// Hochberg (1995, "BH"), Benjamini & Yekutieli (2001, "BY"), and none. NaN entries (a comparison
// that could not be made) stay NaN and do not count in n, as p.adjust's n = sum(!is.na(p)).
#include <string>
#include <string_view>
#include <vector>

namespace tlab::analysis {

enum class PAdjustMethod { None, Bonferroni, Holm, Hochberg, BH, BY };

std::string_view pAdjustName(PAdjustMethod method);  // R's names: "none", "bonferroni", "holm", ...
// Accepts R's names (and "fdr" for BH, case-insensitive); throws AnalysisError otherwise.
PAdjustMethod parsePAdjustMethod(std::string_view text);

std::vector<double> pAdjust(const std::vector<double>& p, PAdjustMethod method);

}  // namespace tlab::analysis
