#pragma once
// The timing record of a study (PsychoPy's frame-interval record, per session and per trial):
// which tlab build (version+revision), display and GL renderer each session ran on, its refresh
// rate and swap interval, and per trial the stimulus-request-to-swap delay, the interval of the
// onset frame and the late frames (over 1.5 refresh intervals). Shown by `tlab timing` and in the
// report of a database.
#include "analysis/text_table.hpp"
#include "study/store/store.hpp"
#include "study/store/study_table.hpp"

namespace tlab::study {

analysis::TextTable sessionTimingTable(Store& store, const StoredExperiment& stored);
analysis::TextTable trialTimingTable(Store& store, const StoredExperiment& stored);

}  // namespace tlab::study
