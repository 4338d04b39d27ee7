#pragma once
// StudyAnalysis: runs the experiment's analysis plan on its database — for every [[analysis]] and
// every dependent variable, analysis::makeReport on the adapter's Table, merged into one Report
// per analysis, plus pairwise paired t-tests for within factors with more than two levels when
// t-tests are planned (Carnecky Table 1 compares three methods pairwise; their p-values adjusted as
// `correction` says), plus with tests = ["mixed"] a mixed model per dependent variable and task
// (study_mixed_model.hpp). Every planned p-value is
// listed by name, which is what the power analysis counts. Each task is analysed on its own
// ("correct [task layer-index]") unless the analysis names its tasks or a task cannot be analysed
// alone; then the tasks are pooled and a note says so. The report starts with a warning when the
// participants were simulated; `tlab report` appends the questionnaire answers and the stimuli
// shown (study_record_tables.hpp).
#include <string>
#include <vector>

#include "analysis/mixed_model.hpp"
#include "analysis/report.hpp"
#include "analysis/ttest.hpp"
#include "study/store/study_table.hpp"

namespace tlab::study {

struct PairwiseComparison {
  std::string dv;
  std::string factor;
  std::string first;
  std::string second;
  analysis::TTestResult test;
  double pAdjusted = 1.0;  // by the analysis's correction over the comparisons of this factor
};

// tests = ["mixed"]: one mixed model per dependent variable (and task).
struct MixedModelFit {
  std::string dv;  // "correct [task layer-index]"
  analysis::MixedModelResult result;
};

struct PlannedPValue {
  std::string name;  // "correct: anova method", "rt: transparency t-test", "correct: method alpha vs smart"
  double p = 1.0;
};

struct StudyAnalysis {
  AnalysisSpec spec;
  analysis::Report report;
  std::vector<PairwiseComparison> pairwise;
  std::vector<MixedModelFit> mixed;
  std::vector<std::string> errors;  // a dependent variable whose report could not be made
  std::vector<PlannedPValue> pValues() const;
};

std::vector<StudyAnalysis> analyzeStudy(Store& store, const StoredExperiment& stored);

}  // namespace tlab::study
