// tlab simulate EXPERIMENT.toml --participants N --db sim.db [--size WxH] [--first K] [--resume] [--replicate R]: the study
// run by simulated observers through the same runner (no window, headless rendering); progress
// lines per participant (--trials: per committed response), then trials per second. With
// --replicate R: a power analysis — the study repeated R times, and for each planned test how
// often it is significant. With --calibrate carnecky|FILE.csv: the observer's parameters fitted to
// published results by maximum likelihood (study/simulate/observer_calibration.hpp), nothing simulated.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "analysis/text_table.hpp"
#include "app/build_revision.hpp"
#include "app/commands.hpp"
#include "app/style_file_check.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "study/design/experiment_file.hpp"
#include "study/design/stimulus_size.hpp"
#include "study/simulate/observer_calibration.hpp"
#include "study/run/simulated_observer.hpp"
#include "study/simulate/power_analysis.hpp"
#include "study/simulate/study_simulation.hpp"
#include "study/store/open_store.hpp"

namespace tlab::app {

namespace {

struct SimulateOptions {
  std::string experiment;
  int participants = 0;
  int first = 1;
  std::string db;
  bool resume = false;
  int replicates = 0;
  double pace = 0.0;
  bool trials = false;
  std::string calibrate;
  std::string size;  // WxH instead of the experiment's [stimulus] size
};

void printTrial(const study::TrialProgress& p) {
  std::printf("ack %s %d/%d %s block %d %s trial %d q%d answer=%s %s rt=%s\n", p.participant.c_str(), p.index, p.total,
              study::phaseName(p.plan->phase), p.plan->block, p.plan->taskId.c_str(),
              p.plan->trial, p.plan->question, p.answer ? p.answer->c_str() : "(missing)", p.correct ? "correct" : "wrong",
              p.rtSeconds ? std::to_string(*p.rtSeconds).c_str() : "-");
  std::fflush(stdout);
}

void runPower(const study::Experiment& e, const SimulateOptions& o, study::StimulusLibrary& stimuli, int participants) {
  study::PowerOptions p;
  p.replicates = o.replicates;
  p.participants = participants;
  p.workDirectory = (std::filesystem::path(o.db).parent_path() / (std::filesystem::path(o.db).stem().string() + "-replicates")).string();
  std::filesystem::create_directories(p.workDirectory);
  p.tlabVersion = versionString();
  p.progress = [&](int r, double seconds) {
    std::printf("replicate %d/%d: %d participants simulated in %.2f s\n", r, o.replicates, participants, seconds);
    std::fflush(stdout);
  };
  const auto entries = study::powerAnalysis(e, stimuli, p);
  std::filesystem::remove_all(p.workDirectory);
  analysis::TextTable table;
  table.caption = "Simulated power with " + std::to_string(participants) + " participants, " + std::to_string(o.replicates) + " replicates";
  table.header = {"planned test", "significant", "power", "alpha"};
  for (const auto& entry : entries) {
    char power[32], alpha[32];
    std::snprintf(power, sizeof power, "%.3f", entry.power());
    std::snprintf(alpha, sizeof alpha, "%g", entry.alpha);
    table.rows.push_back({entry.test, std::to_string(entry.significant) + "/" + std::to_string(entry.replicates), power, alpha});
  }
  std::fputs(analysis::renderPlainText(table).c_str(), stdout);
  if (entries.empty()) std::printf("the experiment file plans no analysis ([[analysis]]): nothing to count\n");
}

std::string fixed(double v, const char* format = "%.4f") {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

void printCalibration(const study::PublishedResults& published, const study::CalibrationFit& fit) {
  analysis::TextTable table;
  table.caption = "Fit of the simulated observer to " + published.source + " (factor " + published.factor + ")";
  table.header = {"level", "n", "published mean", "fitted mean", "mean before", "published variance", "fitted variance", "variance before"};
  for (const auto& r : fit.rows)
    table.rows.push_back({r.published.level, std::to_string(r.published.n), fixed(r.published.mean), fixed(r.predicted.mean),
                          fixed(r.atStart.mean), fixed(r.published.variance), fixed(r.predicted.variance), fixed(r.atStart.variance)});
  std::fputs(analysis::renderPlainText(table).c_str(), stdout);
  std::printf("parameters: sensitivity %.4g (was %.4g), threshold %.4g (was %.4g), skill_spread %.4g (was %.4g); others as in [observer]\n",
              fit.params.sensitivity, fit.start.sensitivity, fit.params.threshold, fit.start.threshold, fit.params.skillSpread,
              fit.start.skillSpread);
  std::printf("log-likelihood %.4f (at the experiment's parameters %.4f), %d evaluations, Nelder-Mead %s\n", fit.logLikelihood,
              fit.startLogLikelihood, fit.evaluations, fit.converged ? "converged" : "stopped at its evaluation limit");
  for (const auto& note : fit.notes) std::printf("note: %s\n", note.c_str());
  std::printf("paste into the experiment file to simulate with the fitted observer:\n\n%s", study::observerToml(fit.params).c_str());
}

void runCalibration(const study::Experiment& e, const SimulateOptions& o, int participants) {
  const study::PublishedResults published =
      o.calibrate == "carnecky" ? study::carneckyPublishedResults() : study::readPublishedResults(o.calibrate);
  const auto context = gpu::createHeadlessContext();
  study::TextPainter painter;
  const bool temporary = o.db.empty();
  const std::string directory = temporary ? (std::filesystem::temp_directory_path() / ("tlab-calibration-" + e.id + "-" + std::to_string(::getpid()))).string()
                                          : study::stimulusDirectoryFor(o.db);
  study::StimulusLibrary stimuli(directory, sceneCatalog(), painter);
  const auto questions = study::predictionQuestions(e, stimuli, published.factor, participants);
  if (temporary) std::filesystem::remove_all(directory);
  std::size_t count = 0;
  for (const auto& [level, qs] : questions) count += qs.size();
  std::printf("%zu test questions of %d participants prepared; fitting sensitivity, threshold, skill_spread\n", count, participants);
  printCalibration(published, study::calibrateObserver(e.observer, questions, published));
}

// The experiment file, at --size when given (the stored text then says that size).
study::Experiment readExperiment(const SimulateOptions& o) {
  const study::Experiment e = study::readExperimentFile(o.experiment);
  if (o.size.empty()) return e;
  parseSize(o.size);  // "--size: ..." before the file's own check
  return study::withStimulusSize(e, o.size);
}

void run(const SimulateOptions& o) {
  const study::Experiment e = readExperiment(o);
  checkExperimentOnGl(e);  // a broken style file or a misaligned image: one line, before any session
  if (o.participants < 0) throw std::invalid_argument("--participants: must be >= 1");
  const int participants = o.participants > 0 ? o.participants : e.participants;
  if (o.first < 1) throw std::invalid_argument("--first: must be >= 1");
  if (o.replicates < 0) throw std::invalid_argument("--replicate: must be >= 1");
  if (o.pace < 0) throw std::invalid_argument("--pace: must be >= 0");
  if (!o.calibrate.empty()) return runCalibration(e, o, participants);
  if (o.db.empty()) throw std::invalid_argument("--db: required (the study database to write)");
  const auto context = gpu::createHeadlessContext();
  study::TextPainter painter;
  study::StimulusLibrary stimuli(study::stimulusDirectoryFor(o.db), sceneCatalog(), painter);
  if (o.replicates > 0) return runPower(e, o, stimuli, participants);
  const auto storeOwner = study::openStore(o.db);
  study::Store& store = *storeOwner;
  study::SimulationOptions s;
  s.participants = participants;
  s.firstParticipant = o.first;
  s.resume = o.resume;
  s.paceSeconds = o.pace;
  s.observerSeed = e.seed;
  s.tlabVersion = versionString();
  const gpu::GpuInfo gl = context->info();
  s.renderer = study::DisplayInfo{gl.backend, gl.vendor, gl.renderer, gl.version, 0, 0, 0, 0, 0, 0};
  s.log = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  if (o.trials) s.progress = printTrial;
  const study::SimulationResult r = study::simulateStudy(e, store, stimuli, s);
  std::printf("simulated %d participants, %d trials in %.3f s (%.1f trials/s) into %s\n", r.participantsRun, r.trialsAnswered, r.seconds,
              r.seconds > 0 ? r.trialsAnswered / r.seconds : 0.0, o.db.c_str());
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("simulate", "Run an experiment with simulated observers (no window); --replicate R: power analysis; --calibrate: fit the observer to published results");
  cmd->footer("What a simulated observer is (defaults shown; [observer] in the experiment file sets them): " +
              study::describeSimulatedObserver(study::ObserverParams{}));
  auto o = std::make_shared<SimulateOptions>();
  cmd->add_option("experiment", o->experiment, "experiment file (TOML)")->required();
  cmd->add_option("--participants", o->participants, "simulated participants (default: the experiment's)");
  cmd->add_option("--db", o->db, "study database to write (required unless --calibrate)");
  cmd->add_option("--first", o->first, "number of the first simulated participant (sim-<first>...; a second station takes another range)")
      ->capture_default_str();
  cmd->add_flag("--resume", o->resume, "continue: skip finished simulated participants, resume an interrupted one");
  cmd->add_option("--replicate", o->replicates, "power analysis: repeat the study R times and count significant planned tests");
  cmd->add_option("--pace", o->pace, "real seconds slept per simulated second of response time (default 0: as fast as possible)");
  cmd->add_flag("--trials", o->trials, "print a line for every committed response");
  cmd->add_option("--size", o->size, "stimulus size WxH instead of the experiment's [stimulus] size (a reduced pilot; the stored "
                                     "experiment text says the size used)");
  cmd->add_option("--calibrate", o->calibrate,
                  "fit sensitivity, threshold and skill_spread by maximum likelihood to published results: 'carnecky' "
                  "(Table 1) or a CSV file with columns factor,level,n,mean,variance (per-participant proportion correct); "
                  "--participants sets how many design slots are prepared");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
