#include "study/analyze/replay_listing.hpp"

#include <cctype>

namespace tlab::study {

std::vector<ReplayableTrial> replayableTrials(Store& store, const std::string& experimentId) {
  std::vector<ReplayableTrial> out;
  for (const auto& row : store.liveTrials(experimentId).rows) out.push_back({row[0], std::stoi(row[1]), row[2], row[3], std::stoi(row[4])});
  return out;
}

std::string shellQuoted(const std::string& word) {
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string replayCommand(const std::string& location, const ReplayableTrial& trial) {
  std::string name;  // a file name from any participant id
  for (unsigned char c : trial.participant) name += std::isalnum(c) || c == '-' || c == '_' ? char(c) : '_';
  const std::string page = "replay-" + name + "-trial" + std::to_string(trial.sequence) + ".html";
  return "tlab replay " + shellQuoted(location) + " --participant " + shellQuoted(trial.participant) + " --trial " +
         std::to_string(trial.sequence) + " --html " + shellQuoted(page);
}

analysis::TextTable replayTable(Store& store, const std::string& location, const std::string& experimentId) {
  analysis::TextTable t;
  t.caption = "Interactive trials with their live frames logged: each replays with the command beside it (every frame rendered again "
              "from its logged camera and checked against its logged SHA-256; --html writes a page with the frames, inputs, timing and "
              "answer, -o a video)";
  t.header = {"participant", "trial", "phase", "task", "frames", "replay"};
  for (const auto& r : replayableTrials(store, experimentId))
    t.rows.push_back({r.participant, std::to_string(r.sequence), r.phase, r.taskId, std::to_string(r.frames), replayCommand(location, r)});
  return t;
}

}  // namespace tlab::study
