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

std::string replayStem(const ReplayableTrial& trial) {
  std::string name;  // a file name from any participant id
  for (unsigned char c : trial.participant) name += std::isalnum(c) || c == '-' || c == '_' ? char(c) : '_';
  return "replay-" + name + "-trial" + std::to_string(trial.sequence);
}

std::string replayCommand(const std::string& location, const ReplayableTrial& trial) {
  const std::string page = replayStem(trial) + ".html";
  return "tlab replay " + shellQuoted(location) + " --participant " + shellQuoted(trial.participant) + " --trial " +
         std::to_string(trial.sequence) + " --html " + shellQuoted(page);
}

analysis::TextTable replayTable(Store& store, const std::string& location, const std::string& experimentId, const ReplayLinks& links) {
  analysis::TextTable t;
  t.caption = "Interactive trials with their live frames logged: each replays with the command beside it (every frame rendered again "
              "from its logged camera and checked against its logged SHA-256; --html writes a page with the frames, inputs, timing and "
              "answer, -o a video)";
  t.caption += links.empty() ? "; tlab report --replays renders each and links its page here"
                             : "; the replay page column links to the page tlab report --replays rendered, with its check";
  t.header = {"participant", "trial", "phase", "task", "frames", "replay"};
  if (!links.empty()) t.header.push_back("replay page");
  for (const auto& r : replayableTrials(store, experimentId)) {
    t.rows.push_back({r.participant, std::to_string(r.sequence), r.phase, r.taskId, std::to_string(r.frames), replayCommand(location, r)});
    if (links.empty()) continue;
    const auto link = links.find({r.participant, r.sequence});
    t.rows.back().push_back(link == links.end() ? "not rendered" : link->second.check);
    t.links.resize(t.rows.size());
    if (link != links.end()) t.links.back() = {"", "", "", "", "", "", link->second.href};
  }
  return t;
}

}  // namespace tlab::study
