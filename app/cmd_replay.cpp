// tlab replay DB --participant P --trial N [-o replay.webm] [--frames DIR] [--html replay.html]:
// every live frame of an interactive trial rendered again from its logged camera (and lens) and
// checked against its logged SHA-256 — "N of N frames identical", or which differ and why (another
// GL, another tlab version), exiting 1 then. The database is opened read-only.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <unistd.h>

#include "app/build_revision.hpp"
#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "core/image.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "study/replay/replay_outputs.hpp"
#include "study/replay/trial_replay.hpp"
#include "study/store/open_store.hpp"

namespace tlab::app {

namespace {

namespace fs = std::filesystem;

struct ReplayOptions {
  std::string db;
  std::string participant;
  int trial = 0;
  std::string experiment;
  std::string video;
  std::string frames;
  std::string html;
};

// A folder for frames that only the video needs, removed when the replay ends.
struct ScratchFolder {
  fs::path path;
  ScratchFolder() : path(fs::temp_directory_path() / ("tlab-replay-" + std::to_string(::getpid()))) { fs::create_directories(path); }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

void writeText(const fs::path& path, const std::string& text) {
  core::writeFileAtomically(path.string(), std::vector<std::uint8_t>(text.begin(), text.end()));
}

void run(const ReplayOptions& o) {
  if (o.trial < 1) throw std::invalid_argument("--trial: the trial's sequence, 1 or more");
  const auto store = study::openStore(o.db, study::OpenMode::Read);
  const study::LoggedTrial trial = study::loadLoggedTrial(*store, o.experiment, o.participant, o.trial);
  const auto context = gpu::createHeadlessContext();
  const study::ReplayRenderer self{context->info().renderer, versionString()};
  std::printf("replay of %s (task %s, %s, %s %dx%d): %zu frames logged\n", study::trialName(trial).c_str(), trial.plan.taskId.c_str(),
              study::navigationName(trial.plan.navigation), trial.plan.stimulus.style.c_str(), trial.plan.stimulus.width,
              trial.plan.stimulus.height, trial.frames.size());

  // Where the PNG frames go: --frames, the page's own folder, a scratch folder for the video.
  std::vector<fs::path> folders;
  if (!o.frames.empty()) folders.push_back(o.frames);
  const fs::path pageFrames = o.html.empty() ? fs::path() : study::pageFramesFolder(o.html);
  if (!o.html.empty()) folders.push_back(pageFrames);
  std::unique_ptr<ScratchFolder> scratch;
  if (!o.video.empty() && folders.empty()) folders.push_back((scratch = std::make_unique<ScratchFolder>())->path);

  const study::ReplayCheck check = study::replayIntoFolders(trial, sceneCatalog(), self, folders);
  if (!o.frames.empty()) std::printf("wrote %zu frames to %s\n", trial.frames.size(), o.frames.c_str());
  if (!o.video.empty()) {
    study::writeReplayVideo(trial, folders.front(), o.video);
    std::printf("wrote %s\n", o.video.c_str());
  }
  if (!o.html.empty()) {
    writeText(o.html, study::replayPage(trial, check, pageFrames.filename().string()));
    std::printf("wrote %s (frames in %s)\n", o.html.c_str(), pageFrames.string().c_str());
  }
  for (std::size_t i = 0; i < check.frames.size(); ++i) {
    const study::FrameCheck& f = check.frames[i];
    if (f.identical) continue;
    std::printf("frame %zu (session %lld, index %d, input \"%s\") differs: logged %s, replayed %s; %s\n", i,
                static_cast<long long>(trial.frames[i].session), trial.frames[i].frame.index, trial.frames[i].frame.input.c_str(),
                trial.frames[i].frame.sha256.substr(0, 16).c_str(), f.replayedSha256.substr(0, 16).c_str(), f.why.c_str());
  }
  std::printf("%s\n", check.summary().c_str());
  std::fflush(stdout);
  if (check.identical() != int(check.frames.size()))
    throw std::runtime_error(std::to_string(check.frames.size() - std::size_t(check.identical())) + " of " +
                             std::to_string(check.frames.size()) + " frames differ from the log (listed above)");
}

}  // namespace

void addReplayCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("replay", "Render an interactive trial's logged frames again and check each against its logged hash");
  auto o = std::make_shared<ReplayOptions>();
  cmd->add_option("db", o->db, "study database (a file or a postgresql:// URL), opened read-only")->required();
  cmd->add_option("--participant", o->participant, "participant id, as stored")->required();
  cmd->add_option("--trial", o->trial,
                  "the trial's sequence: its 1-based place in the participant's session, as in the `sequence` column of tlab export's "
                  "trials.csv (and `trial_sequence` of events.csv)")
      ->required();
  cmd->add_option("--experiment", o->experiment, "experiment id (when the database holds several)");
  cmd->add_option("-o,--output", o->video, "video of the frames at their logged times (ffmpeg: .webm VP9, .mp4 H.264)");
  cmd->add_option("--frames", o->frames, "folder for the frames as PNG files (frame-000000.png, ... in the order shown)");
  cmd->add_option("--html", o->html, "an HTML page with the frames (in a folder NAME-frames beside it), the inputs, the timing and the answer");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
