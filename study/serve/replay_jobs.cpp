#include "study/serve/replay_jobs.hpp"

#include <fstream>
#include <regex>

#include <unistd.h>

#include "core/file_text.hpp"
#include "study/serve/participant_session.hpp"

namespace tlab::study {

namespace fs = std::filesystem;

namespace {

// The line of tlab replay's output that gives its verdict ("7 of 7 frames identical").
std::string verdict(const fs::path& log) {
  std::ifstream in(log);
  const std::regex summary("^[0-9]+ of [0-9]+ frames? identical$");
  std::string line, found;
  while (std::getline(in, line))
    if (std::regex_match(line, summary)) found = line;
  return found;
}

}  // namespace

ReplayJobs::ReplayJobs(std::string program, std::string location, std::string experimentId)
    : program_(std::move(program)), location_(std::move(location)), experimentId_(std::move(experimentId)) {}

ReplayJobs::~ReplayJobs() {
  jobs_.clear();  // each running child is stopped and reaped before its folder goes
  if (root_.empty()) return;
  std::error_code ignored;
  fs::remove_all(root_, ignored);
}

const fs::path& ReplayJobs::root() {
  if (root_.empty()) {
    fs::path root = fs::temp_directory_path() / ("tlab-serve-replays-" + std::to_string(::getpid()) + "-" + newToken().substr(0, 8));
    fs::create_directories(root);
    root_ = std::move(root);
  }
  return root_;
}

void ReplayJobs::update(Job& job) {
  if (job.state.kind != ReplayJobState::Kind::Rendering) return;
  const auto status = job.process->poll();
  if (!status) return;
  const fs::path log = job.folder / "replay.log";
  // tlab replay exits 1 when frames differ: its page is written all the same and says which.
  const std::string said = verdict(log);
  if ((*status == 0 || *status == 1) && !said.empty() && fs::exists(job.folder / "replay.html")) {
    job.state.kind = ReplayJobState::Kind::Done;
    job.state.message = said;
  } else {
    job.state.kind = ReplayJobState::Kind::Failed;
    const std::string last = core::lastNonEmptyLine(core::readFileText(log.string()).value_or(""));
    job.state.message = last.empty() ? "tlab replay ended with status " + std::to_string(*status) : last;
  }
  job.process.reset();
}

std::string ReplayJobs::request(const std::string& participant, int sequence, int frames) {
  std::lock_guard lock(mutex_);
  int running = 0;
  for (auto& [key, job] : jobs_) {
    update(job);
    running += job.state.kind == ReplayJobState::Kind::Rendering;
  }
  if (const auto it = latest_.find({participant, sequence}); it != latest_.end()) {
    const ReplayJobState& s = jobs_.at(it->second).state;
    if (s.frames == frames && s.kind != ReplayJobState::Kind::Failed) return it->second;
  }
  if (running >= kMaxRunning)
    throw ReplayBusy(std::to_string(running) + " replays are rendering; ask again when one of them is done");
  const std::string key = newToken().substr(0, 32);
  Job job;
  job.state = {ReplayJobState::Kind::Rendering, participant, sequence, frames, ""};
  job.folder = root() / key;
  fs::create_directories(job.folder);
  // The lowest priority: participants' frames and answers come first on the server's CPUs.
  job.process = std::make_unique<core::ChildProcess>(
      std::vector<std::string>{"nice", "-n", "19", program_, "replay", "--participant=" + participant, "--trial=" + std::to_string(sequence),
                               "--experiment=" + experimentId_, "--html=" + (job.folder / "replay.html").string(), "--", location_},
      job.folder / "replay.log");
  jobs_.emplace(key, std::move(job));
  latest_[{participant, sequence}] = key;
  return key;
}

std::optional<ReplayJobState> ReplayJobs::state(const std::string& key) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(key);
  if (it == jobs_.end()) return std::nullopt;
  update(it->second);
  return it->second.state;
}

std::optional<fs::path> ReplayJobs::file(const std::string& key, const std::string& name) {
  static const std::regex served("replay\\.html|replay-frames/frame-[0-9]{6}\\.png");
  if (!std::regex_match(name, served)) return std::nullopt;
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(key);
  if (it == jobs_.end()) return std::nullopt;
  update(it->second);
  if (it->second.state.kind != ReplayJobState::Kind::Done) return std::nullopt;
  const fs::path path = it->second.folder / name;
  if (!fs::is_regular_file(path)) return std::nullopt;
  return path;
}

}  // namespace tlab::study
