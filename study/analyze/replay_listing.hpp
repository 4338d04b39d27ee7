#pragma once
// The interactive trials of a study whose live frames were logged, and the `tlab replay` command
// that re-renders each and checks it against the log: what the admin page of `tlab serve` and the
// report of a study database list, so a researcher can look at what any participant did.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "analysis/text_table.hpp"
#include "study/store/store.hpp"

namespace tlab::study {

struct ReplayableTrial {
  std::string participant;
  int sequence = 0;  // the trial's place in the participant's session (tlab replay --trial)
  std::string phase;
  std::string taskId;
  int frames = 0;
};

// In participant and sequence order.
std::vector<ReplayableTrial> replayableTrials(Store& store, const std::string& experimentId);

// A word quoted for a POSIX shell: 'it'\''s'.
std::string shellQuoted(const std::string& word);

// tlab replay 'study.db' --participant 'P1' --trial 3 --html 'replay-P1-trial3.html'
std::string replayCommand(const std::string& location, const ReplayableTrial& trial);

// A replay page written for a trial (tlab report --replays): its address relative to the report
// and the check of its frames ("7 of 7 frames identical").
struct ReplayLink {
  std::string href;
  std::string check;
};
using ReplayLinks = std::map<std::pair<std::string, int>, ReplayLink>;  // by participant and sequence

// The report's table of them, with the command of each and, where `links` has its page, a column
// linking to it; no rows when no frames were logged.
analysis::TextTable replayTable(Store& store, const std::string& location, const std::string& experimentId, const ReplayLinks& links = {});

// "replay-P1-trial3": the file stem of a trial's replay page, from any participant id.
std::string replayStem(const ReplayableTrial& trial);

}  // namespace tlab::study
