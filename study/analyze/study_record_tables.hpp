#pragma once
// StudyRecordTables: what a report of a study database shows besides the tests — who the
// participants were (people or simulated observers), the questionnaire answers, and the stimuli
// that were shown. Read-only queries on the store's database; the summaries themselves are
// computed by analysis/ (study computes no statistics).
#include <string>
#include <vector>

#include "analysis/report.hpp"
#include "analysis/text_table.hpp"
#include "study/analyze/replay_listing.hpp"
#include "study/store/study_table.hpp"

namespace tlab::study {

struct ParticipantModes {
  int participants = 0;  // with at least one session
  int simulated = 0;     // whose sessions were all run by a simulated observer
  int mixed = 0;         // with simulated and other sessions
};

ParticipantModes participantModes(Store& store, const StoredExperiment& stored);

// The line a report of (partly) simulated data starts with; empty when every participant is a person.
std::string simulatedDataWarning(const ParticipantModes& modes, const ObserverParams& observer);

// One table per questionnaire of the experiment that has answers (dropped participants left out).
std::vector<analysis::TextTable> questionnaireTables(Store& store, const StoredExperiment& stored);

// Every stimulus shown: condition, task, phase, file, SHA-256, trials and participants.
analysis::TextTable stimulusTable(Store& store, const StoredExperiment& stored);

// The test stimuli as participants saw them (the first question's picture of each condition and
// task, at most `limit`), read from the stimulus files next to the database; files that are no
// longer there are left out (the table above still names them).
std::vector<analysis::ReportImage> stimulusImages(Store& store, const StoredExperiment& stored, std::size_t limit = 64);

// The questionnaire tables, the stimulus table, the session timing, the interactive trials with
// the command that replays each (when frames were logged; with a link to the pages `replays` names)
// and the stimulus pictures appended to a report.
void appendStudyRecord(analysis::Report& report, Store& store, const StoredExperiment& stored, const ReplayLinks& replays = {});

}  // namespace tlab::study
