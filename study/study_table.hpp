#pragma once
// The thin adapter from the study database to analysis/: the experiment stored in the database,
// and for one analysis of its plan and one dependent variable, an analysis::Table with one row
// per answered-or-missing test record: participant, every factor (level names), task, block and
// the dependent variable. Training records and dropped-out participants are left out; records
// without a value for the variable (e.g. the RT of a missing answer) are left out of that table.
#include <cstdint>
#include <string>

#include "analysis/report.hpp"
#include "analysis/table.hpp"
#include "study/experiment.hpp"
#include "study/session_store.hpp"

namespace tlab::study {

struct StoredExperiment {
  std::int64_t row = 0;
  Experiment experiment;
};

// The experiment of the database (its stored file text, parsed again). With several experiments
// in one database, `experimentId` chooses; throws StoreError listing them otherwise.
StoredExperiment storedExperiment(SessionStore& store, const std::string& experimentId = "");

analysis::Table analysisTable(SessionStore& store, const StoredExperiment& stored, const AnalysisSpec& spec,
                              const std::string& dependentVariable);

// The AnalysisPlan of an analysis spec for one dependent variable (subject column "participant").
analysis::AnalysisPlan analysisPlan(const AnalysisSpec& spec, const std::string& dependentVariable);

}  // namespace tlab::study
