#pragma once
// Report: everything an analysis plan produces for a Table — the design, descriptives and outlier
// screening per cell, the ANOVA, the two-condition and rank tests, and the figures — ready to be
// rendered as HTML (report_html) or Markdown (report_markdown).
//
// The study library's SQLite adapter only has to build a Table and an AnalysisPlan from the
// experiment file; `makeReport(table, plan)` does the rest.
#include <optional>
#include <string>
#include <vector>

#include "analysis/anova.hpp"
#include "analysis/descriptives.hpp"
#include "analysis/outliers.hpp"
#include "analysis/rank_tests.hpp"
#include "analysis/table.hpp"
#include "analysis/text_table.hpp"
#include "analysis/ttest.hpp"

namespace tlab::analysis {

enum class PlannedTest {
  Anova,      // between / repeated-measures / mixed ANOVA over all factors
  TTests,     // per two-level factor: paired (within) or Welch (between) t-test on marginal means
  RankTests,  // per within factor: Wilcoxon (2 levels) or Friedman (> 2); per 2-level between: Mann-Whitney
};

struct AnalysisPlan {
  std::string title = "Analysis report";
  std::vector<std::string> dependentVariables;
  std::vector<std::string> between;
  std::vector<std::string> within;
  std::string subject;  // required with within factors
  std::vector<PlannedTest> tests = {PlannedTest::Anova, PlannedTest::TTests, PlannedTest::RankTests};
  SumOfSquaresType ssType = SumOfSquaresType::II;
  double confidence = 0.95;
  // Dependent variables that are proportions or scores in [0, 1] (a dependent variable whose
  // values are all 0 or 1 counts as one anyway): their plots' axes end at 0 and 1.
  std::vector<std::string> proportions{};
};

// One cell of the design (a combination of all factors' levels), over subjects (replicates of a
// subject in a cell averaged first).
struct CellSummary {
  std::vector<std::string> levels;  // between factors' levels, then within factors'
  std::string label;                // "group=a, time=t1"
  std::vector<double> values;
  std::vector<std::string> subjects;  // parallel to values
  std::optional<Descriptives> stats;  // empty when n < 2 (see error)
  OutlierScreen outliers;
  std::string error;
};

struct Comparison {
  std::string factor;
  std::string description;  // "time: t1 vs t2, paired over 16 subjects"
  std::optional<TTestResult> tTest;
  std::optional<WilcoxonSignedRankResult> wilcoxon;
  std::optional<MannWhitneyResult> mannWhitney;
  std::optional<FriedmanResult> friedman;
  std::string error;
};

struct Figure {
  std::string caption;
  std::string svg;
};

struct DependentVariableReport {
  std::string dv;
  bool proportion = false;  // on the scale [0, 1] (AnalysisPlan::proportions): plots end at 0 and 1
  std::vector<CellSummary> cells;
  std::optional<AnovaResult> anova;
  std::string anovaError;
  std::vector<Comparison> comparisons;
  std::vector<Figure> figures;
};

struct DesignSummary {
  std::size_t rows = 0;
  std::size_t subjects = 0;
  std::size_t maxReplicates = 1;
  std::vector<FactorLevels> between;
  std::vector<FactorLevels> within;
  std::string subject;
};

// A picture the report shows as it is (e.g. a stimulus as participants saw it).
struct ReportImage {
  std::string caption;
  std::string mimeType;  // "image/png"
  std::string bytes;
};

// A titled part of a report that a caller fills (e.g. a mixed model of study/: its description,
// warnings and tables), rendered after the dependent variables.
struct ReportSection {
  std::string heading;
  std::vector<std::string> paragraphs;
  std::vector<std::string> warnings;
  std::vector<TextTable> tables;
};

struct Report {
  std::string title;
  std::string source;
  AnalysisPlan plan;
  DesignSummary design;
  std::vector<DependentVariableReport> dependentVariables;
  std::vector<std::string> notes;     // how the numbers were computed, each once
  std::vector<std::string> warnings;  // what a reader must know first (e.g. simulated data): at the top
  std::vector<ReportSection> sections;  // after the dependent variables (mixed models)
  std::vector<TextTable> appendices;  // further tables after the dependent variables (questionnaires, stimuli)
  std::vector<ReportImage> images;    // a gallery at the end (the stimuli shown)
};

// Throws AnalysisError for plan errors (missing columns, no dv, within without subject,
// unbalanced within data, non-numeric values); test-level problems (zero variance, n < 2 in a
// cell) are recorded in the report instead, so one bad cell does not hide the rest.
Report makeReport(const Table& table, const AnalysisPlan& plan);

}  // namespace tlab::analysis
