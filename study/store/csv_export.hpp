#pragma once
// Tidy long-format CSV export of a study database, readable as is by R (read.csv) and pandas
// (read_csv): RFC 4180 quoting, one header row, one observation per row, empty cells for missing
// values, text exactly as stored (bytes unchanged, so invalid UTF-8 survives a round trip).
//   trials.csv          one row per trial record (with its response, if any) and one column per factor
//   questionnaires.csv  one row per questionnaire item answer (the answer as given, its number)
//   participant_info.csv one row per participant-information field
//   consent.csv         one row per consent decision (a decline is all that is stored of a decliner)
//   sessions.csv        one row per session: version, station, status (finished / closed / interrupted,
//                       resumed by session N / running), responses and stimulus onsets in it
//   participants.csv    one row per participant with slot, design row and status
//   events.csv          one row per event (pause, resume, layout, timing, responses)
#include <string>
#include <vector>

#include "study/store/store.hpp"
#include "study/store/study_table.hpp"

namespace tlab::study {

// A CSV field: quoted when it holds a comma, quote, CR, LF or leading/trailing blank.
std::string csvField(const std::string& text);

// Writes the seven files into `directory` (created if needed); returns their paths.
std::vector<std::string> exportCsv(Store& store, const StoredExperiment& stored, const std::string& directory);

}  // namespace tlab::study
