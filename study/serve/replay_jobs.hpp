#pragma once
// ReplayJobs: the replays the admin page of `tlab serve` links to. Each is rendered by a
// `tlab replay --html` child process at the lowest CPU priority (nice 19) — never on the GL worker
// that renders participants' frames, whose answers come first — into a folder of its own under a
// temporary folder that is removed when the server stops. A replay is addressed by an unguessable
// key, as a participant's session is by its token, so its page can fetch its frames by relative
// links without the admin token in each; the admin token is needed to get the key. A trial
// requested again with more frames logged since is rendered anew; with the same frames, the replay
// already made is served.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/child_process.hpp"

namespace tlab::study {

// More replays asked for while kMaxRunning render.
struct ReplayBusy : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ReplayJobState {
  enum class Kind { Rendering, Done, Failed };
  Kind kind = Kind::Rendering;
  std::string participant;
  int sequence = 0;
  int frames = 0;
  std::string message;  // Done: the replay's verdict ("7 of 7 frames identical"); Failed: why (its last line)
};

class ReplayJobs {
 public:
  static constexpr int kMaxRunning = 2;

  // `program`: the tlab executable; `location`: the study database as tlab replay opens it.
  ReplayJobs(std::string program, std::string location, std::string experimentId);
  ~ReplayJobs();  // stops replays still rendering and removes their folder
  ReplayJobs(const ReplayJobs&) = delete;
  ReplayJobs& operator=(const ReplayJobs&) = delete;

  // The key of the replay of the participant's trial `sequence` with `frames` logged: the one made
  // or rendering, else a new one started. Throws ReplayBusy when kMaxRunning render already.
  std::string request(const std::string& participant, int sequence, int frames);
  // nullopt: no such key.
  std::optional<ReplayJobState> state(const std::string& key);
  // A file of a finished replay: "replay.html" or "replay-frames/frame-NNNNNN.png" (six digits);
  // nullopt for any other name, an unknown key, a replay not done or a file not there.
  std::optional<std::filesystem::path> file(const std::string& key, const std::string& name);

 private:
  struct Job {
    ReplayJobState state;
    std::filesystem::path folder;
    std::unique_ptr<core::ChildProcess> process;
  };
  void update(Job& job);  // under mutex_
  const std::filesystem::path& root();

  std::string program_, location_, experimentId_;
  std::mutex mutex_;
  std::filesystem::path root_;  // created at the first request
  std::map<std::string, Job> jobs_;                             // by key
  std::map<std::pair<std::string, int>, std::string> latest_;  // the newest key of each trial
};

}  // namespace tlab::study
