// tlab serve EXPERIMENT.toml --db DB [--listen 127.0.0.1:8080]: the study in participants'
// browsers. Every stimulus is prepared first (progress bar), then the server prints the link for
// participants (with the Prolific form of it) and the admin page's address with its token, and
// serves until Ctrl-C or SIGTERM. The store is SQLite by default (a file) or PostgreSQL (a
// postgresql:// URL); stimuli are kept beside the database as for `tlab run`.
#include <csignal>
#include <cstdio>
#include <memory>
#include <thread>

#include "app/build_revision.hpp"
#include "app/commands.hpp"
#include "app/style_file_check.hpp"
#include "app/scene_options.hpp"
#include "study/design/experiment_file.hpp"
#include "study/run/stimulus_library.hpp"
#include "study/run/plan_checks.hpp"
#include "study/serve/study_preparation.hpp"
#include "study/serve/study_server.hpp"
#include "study/store/locked_store.hpp"
#include "study/store/open_store.hpp"

namespace tlab::app {

namespace {

struct ServeCommandOptions {
  std::string experiment;
  std::string db = "study.db";
  std::string listen = "127.0.0.1:8080";
  int threads = 256;  // requests answered at once (idle connections hold none)
  int perAddress = 2000;
  int slots = 0;
  int liveRenderers = 1;  // threads rendering live frames at once, each with its own GL context
  bool quiet = false;
};

std::pair<std::string, int> parseListen(const std::string& text) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0) throw std::invalid_argument("--listen: expected HOST:PORT, got '" + text + "'");
  const std::string port = text.substr(colon + 1);
  char* end = nullptr;
  const long n = std::strtol(port.c_str(), &end, 10);
  if (port.empty() || *end != '\0' || n < 0 || n > 65535) throw std::invalid_argument("--listen: the port must be 0..65535, got '" + port + "'");
  return {text.substr(0, colon), int(n)};
}

// Ctrl-C and SIGTERM stop the server: the signals are blocked in every thread and one thread
// waits for them (no signal handler, no global).
std::thread stopOnSignal(study::StudyServer& server, sigset_t signals) {
  return std::thread([&server, signals] {
    int received = 0;
    sigwait(&signals, &received);
    if (received == SIGUSR1) return;  // the server stopped by itself
    std::fprintf(stderr, "serve: stopping (signal %d); sessions continue where they stopped when the server runs again\n", received);
    server.stop();
  });
}

void serve(const ServeCommandOptions& o) {
  const auto [host, port] = parseListen(o.listen);
  sigset_t signals;
  sigemptyset(&signals);
  for (const int s : {SIGINT, SIGTERM, SIGUSR1}) sigaddset(&signals, s);
  // Blocked before any thread starts (the render worker's and its GL driver's too): threads inherit
  // the mask, and one that took SIGTERM would end the process at once instead of stopping the server.
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  const study::Experiment e = study::readExperimentFile(o.experiment);
  checkExperimentOnGl(e);  // a broken style file or a misaligned image: one line, before any session
  study::checkOnlineExperiment(e);
  study::LockedStore store(study::openStore(o.db));
  study::RenderWorker worker(study::stimulusDirectoryFor(o.db), sceneCatalog(), e.online, o.liveRenderers);
  const study::Design design = study::makeDesign(e);
  const int slots = o.slots > 0 ? o.slots : study::slotsOfOneCycle(design, e.participants);
  // One line per phase, also with --quiet (which hides only the bar): preparing can take minutes.
  std::printf("serve: %s read; store %s open; GL worker on %s\n", o.experiment.c_str(), store.location().c_str(),
              worker.gpuInfo().renderer.c_str());
  std::printf("serve: preparing every stimulus of %d slot%s (one balanced cycle) before listening ...\n", slots, slots == 1 ? "" : "s");
  std::fflush(stdout);
  pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);  // Ctrl-C during the preparation ends tlab as usual
  const study::PreparedStudy prepared = study::prepareStudy(e, worker, slots, !o.quiet);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);  // before any server thread starts
  std::printf("prepared %d images for %d trials of %d slots (GL: %s)\n", prepared.images, prepared.trials, prepared.slots, worker.gpuInfo().renderer.c_str());

  study::ServeOptions options;
  options.host = host;
  options.port = port;
  options.threads = o.threads;
  options.connectionsPerAddress = std::size_t(o.perAddress);
  study::StudyServer server(study::ServedStudy{e, store, worker, versionString()}, options, study::newToken());
  const int bound = server.bind();
  const std::string base = "http://" + host + ":" + std::to_string(bound);
  const std::string& id = e.online.participantParameter;
  std::printf("participants: %s/s/%s?%s=PARTICIPANT-ID\n", base.c_str(), e.id.c_str(), id.c_str());
  if (!e.online.studyParameter.empty() || id == "PROLIFIC_PID")
    std::printf("for Prolific:  %s/s/%s?%s={{%%PROLIFIC_PID%%}}%s%s\n", base.c_str(), e.id.c_str(), id.c_str(),
                e.online.studyParameter.empty() ? "" : ("&" + e.online.studyParameter + "={{%STUDY_ID%}}").c_str(),
                e.online.sessionParameter.empty() ? "" : ("&" + e.online.sessionParameter + "={{%SESSION_ID%}}").c_str());
  std::printf("admin: %s/admin?token=%s\n", base.c_str(), server.adminToken().c_str());
  std::printf("store: %s; listening on %s:%d (Ctrl-C stops)\n", store.location().c_str(), host.c_str(), bound);
  std::fflush(stdout);
  std::thread signalThread = stopOnSignal(server, signals);
  server.listen();
  pthread_kill(signalThread.native_handle(), SIGUSR1);
  signalThread.join();
}

}  // namespace

void addServeCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("serve", "Serve an experiment to participants' browsers (online or across lab stations)");
  auto o = std::make_shared<ServeCommandOptions>();
  cmd->add_option("experiment", o->experiment, "experiment file (TOML; its [online] table sets the link's parameter names)")->required();
  cmd->add_option("--db", o->db, "study database: a file (SQLite) or postgresql://user@host/dbname")->capture_default_str();
  cmd->add_option("--listen", o->listen, "address and port (port 0: any free one; the server binds to this machine only unless told otherwise)")
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "HTTP worker threads (requests answered at once; idle connections hold none)")
      ->capture_default_str()->check(CLI::Range(2, 1024));
  cmd->add_option("--max-connections-per-address", o->perAddress,
                  "open connections one client address may hold; beyond, its longest-idle one is closed")
      ->capture_default_str()->check(CLI::Range(8, 1000000));
  cmd->add_option("--slots", o->slots, "counterbalancing slots to prepare stimuli for (default: one balanced cycle, at most the experiment's participants)");
  cmd->add_option("--live-renderers", o->liveRenderers,
                  "threads that render live views at once, each with its own GL context (each session's frames on one of them)")
      ->capture_default_str()->check(CLI::Range(1, 64));
  cmd->add_flag("--quiet", o->quiet, "no progress bar");
  cmd->callback([o] { serve(*o); });
}

}  // namespace tlab::app
