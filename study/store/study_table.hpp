#pragma once
// The thin adapter from the study database to analysis/: the experiment stored in the database,
// and for one analysis of its plan and one dependent variable, an analysis::Table with one row
// per answered-or-missing test record: participant, every factor (level names), task, block, the
// stimulus (the sha256 of the image shown) and the dependent variable. Training records and dropped-out participants are left out; records
// without a value for the variable (e.g. the RT of a missing answer) are left out of that table.
#include <cstdint>
#include <string>

#include "analysis/report.hpp"
#include "analysis/table.hpp"
#include "study/design/design_fingerprint.hpp"
#include "study/design/experiment.hpp"
#include "study/store/store.hpp"

namespace tlab::study {

// One version of the experiment file and what the database holds of it.
struct StoredVersion {
  ExperimentVersion version;
  std::string design;  // designFingerprint of its text
  int sessions = 0;
};

struct StoredExperiment {
  std::int64_t row = 0;   // the newest version with data (or the newest)
  Experiment experiment;  // its file text, parsed again
  std::vector<StoredVersion> versions;  // the versions the data come from (every version when none has data)
  // "version 1 (file 1a2b3c4d…, design 5e6f…, 12 sessions); version 2 (…)"
  std::string describeVersions() const;
};

// The experiment of the database. With several experiments in one database, `experimentId`
// chooses; throws StoreError listing them otherwise. Data from versions whose designs differ are
// refused (naming the versions) unless `poolVersions`; versions that differ only in text pool.
StoredExperiment storedExperiment(Store& store, const std::string& experimentId = "", bool poolVersions = false);

analysis::Table analysisTable(Store& store, const StoredExperiment& stored, const AnalysisSpec& spec,
                              const std::string& dependentVariable);

// The AnalysisPlan of an analysis spec for one dependent variable (subject column "participant").
analysis::AnalysisPlan analysisPlan(const AnalysisSpec& spec, const std::string& dependentVariable);

}  // namespace tlab::study
