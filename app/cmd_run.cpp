// tlab run EXPERIMENT.toml --participant ID [--db study.db] [--fullscreen] [--resume]: one
// participant's session in a GLFW window — instructions, training, trials (stimulus, countdown,
// answers by click or keyboard), questionnaires. Every response is committed before the next
// stimulus shows; closing the window ends the session cleanly and --resume continues it.
#include <cstdio>
#include <memory>

#include "app/build_revision.hpp"
#include "app/commands.hpp"
#include "app/style_file_check.hpp"
#include "app/scene_options.hpp"
#include "study/design/experiment_file.hpp"
#include "study/run/simulated_observer.hpp"
#include "study/run/trial_runner.hpp"
#include "study/window/window_responder.hpp"
#include "study/store/open_store.hpp"

namespace tlab::app {

namespace {

struct RunCommandOptions {
  std::string experiment;
  std::string participant;
  std::string db = "study.db";
  bool fullscreen = false;
  bool resume = false;
  std::string size = "1024x768";
  bool autopilot = false;
  double autopilotPace = 0.05;
};

void run(const RunCommandOptions& o) {
  if (o.participant.empty()) throw std::invalid_argument("--participant: must not be empty");
  if (o.autopilotPace < 0) throw std::invalid_argument("--autopilot-pace: must be >= 0");
  const study::Experiment e = study::readExperimentFile(o.experiment);
  checkExperimentOnGl(e);  // a broken style file or a misaligned image: one line, before any session
  const auto [width, height] = parseSize(o.size);
  const auto storeOwner = study::openStore(o.db);
  study::Store& store = *storeOwner;
  const study::RunOptions run{o.participant, o.resume, versionString()};
  study::checkParticipant(store, e, run);  // refuse before opening a window
  // The title bar is seen by the participant: the participant title, never the experiment's id or title.
  auto window = study::openParticipantWindow(width, height, "tlab run - " + (e.participantTitle.empty() ? std::string("study") : e.participantTitle));
  if (o.fullscreen) study::makeFullscreen(*window);
  study::TextPainter painter;
  study::StimulusLibrary stimuli(study::stimulusDirectoryFor(o.db), sceneCatalog(), painter);
  study::TrialRunner runner(e, store, stimuli);
  runner.onProgress([](const study::TrialProgress& p) {
    std::printf("trial %d/%d stored (%s)\n", p.index, p.total, p.answer ? "answered" : "missing");
    std::fflush(stdout);
  });
  study::WindowResponder responder(*window, painter);
  if (o.autopilot)
    responder.engageAutopilot(std::make_shared<study::SimulatedObserver>(e.observer, e.seed, o.participant), o.autopilotPace);
  const study::SessionResult r = runner.run(run, responder);
  const study::FrameTiming t = responder.timing();
  std::printf("session %s: %d of %d trials answered in this run (%d before), slot %d\n",
              r.outcome == study::SessionOutcome::Finished   ? "finished"
              : r.outcome == study::SessionOutcome::Declined ? "declined (only the decision was stored)"
                                                             : "closed (continue with --resume)",
              r.answeredNow, r.total, r.answeredBefore, r.slot);
  std::printf("timing: %d frames, present %.3f ms mean / %.3f ms max; onset-to-swap %.3f ms mean / %.3f ms max over %d stimuli; "
              "steady_clock step %.0f ns; longest event wait %.3f ms\n",
              t.frames, t.presentMeanMs, t.presentMaxMs, t.onsetMeanMs, t.onsetMaxMs, t.onsets, t.clockResolutionNs, t.eventWaitMaxMs);
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "Run one participant's session of an experiment in a window");
  auto o = std::make_shared<RunCommandOptions>();
  cmd->add_option("experiment", o->experiment, "experiment file (TOML)")->required();
  cmd->add_option("--participant", o->participant, "participant id (any text; stored as given)")->required();
  cmd->add_option("--db", o->db, "study database")->capture_default_str();
  cmd->add_flag("--fullscreen", o->fullscreen, "full screen on the primary monitor");
  cmd->add_flag("--resume", o->resume, "continue an interrupted session at its first unanswered trial");
  cmd->add_option("--size", o->size, "window size WxH")->capture_default_str();
  cmd->add_flag("--autopilot", o->autopilot,
                "a simulated observer answers every screen through the real window and input handling (check a whole session)");
  cmd->add_option("--autopilot-pace", o->autopilotPace, "real seconds per simulated second of response time")->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
