#pragma once
// The tables of a report (and of `tlab stats` text output) as TextTables, shared by the plain
// text, HTML and Markdown renderings.
#include <vector>

#include "analysis/anova.hpp"
#include "analysis/pairwise_tests.hpp"
#include "analysis/rank_tests.hpp"
#include "analysis/report.hpp"
#include "analysis/text_table.hpp"
#include "analysis/ttest.hpp"

namespace tlab::analysis {

TextTable designTable(const Report& report);
TextTable descriptivesTable(const DependentVariableReport& dv);
TextTable outlierTable(const DependentVariableReport& dv);  // empty rows if nothing was flagged
TextTable anovaTable(const AnovaResult& anova);
TextTable sphericityTable(const AnovaResult& anova);        // empty rows if no effect has q > 1
TextTable comparisonTable(const std::vector<Comparison>& comparisons);
TextTable tTestTable(const TTestResult& t);
TextTable friedmanTable(const FriedmanResult& f);
TextTable wilcoxonTable(const WilcoxonSignedRankResult& w);
TextTable mannWhitneyTable(const MannWhitneyResult& m);
TextTable pairwiseTable(const PairwiseResult& r);

}  // namespace tlab::analysis
