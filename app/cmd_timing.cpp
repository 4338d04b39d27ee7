// tlab timing study.db [--experiment ID] [--pool-versions]: the timing record of a study — per
// session the display, GL renderer, refresh rate and swap interval with onset-to-swap, onset
// frame and late-frame summaries; per trial the same numbers (PsychoPy's frame-interval record).
#include <cstdio>
#include <memory>

#include "analysis/text_table.hpp"
#include "app/commands.hpp"
#include "study/store/open_store.hpp"
#include "study/store/timing_tables.hpp"

namespace tlab::app {

namespace {

struct TimingOptions {
  std::string db;
  std::string experiment;
  bool poolVersions = false;
};

void run(const TimingOptions& o) {
  const auto owner = study::openStore(o.db, study::OpenMode::Read);
  const study::StoredExperiment stored = study::storedExperiment(*owner, o.experiment, o.poolVersions);
  std::fputs(analysis::renderPlainText(study::sessionTimingTable(*owner, stored)).c_str(), stdout);
  std::fputs("\n", stdout);
  const auto trials = study::trialTimingTable(*owner, stored);
  if (trials.rows.empty()) std::printf("no timed trials: every session was simulated (timing exists only for window sessions)\n");
  else std::fputs(analysis::renderPlainText(trials).c_str(), stdout);
}

}  // namespace

void addTimingCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("timing", "Print the timing record of a study database: displays, frame timing per session and per trial");
  auto o = std::make_shared<TimingOptions>();
  cmd->add_option("db", o->db, "study database")->required();
  cmd->add_option("--experiment", o->experiment, "experiment id (when the database holds several)");
  cmd->add_flag("--pool-versions", o->poolVersions, "report data of experiment versions whose designs differ together");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
