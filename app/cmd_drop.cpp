// tlab drop study.db --participant ID [--reason TEXT]: marks a participant as dropped out. Their
// records stay in the database (flagged, left out of the analysis) and their design slot goes to
// the next new participant, so the design stays balanced.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.hpp"
#include "study/store/study_table.hpp"
#include "study/store/open_store.hpp"

namespace tlab::app {

namespace {

struct DropOptions {
  std::string db;
  std::string participant;
  std::string reason = "dropped out";
  std::string experiment;
};

void run(const DropOptions& o) {
  const auto storeOwner = study::openStore(o.db, study::OpenMode::Write);
  study::Store& store = *storeOwner;
  const study::StoredExperiment stored = study::storedExperiment(store, o.experiment, true);
  store.dropParticipant(stored.experiment.id, o.participant, o.reason);
  std::printf("participant dropped; their slot goes to the next new participant\n");
}

}  // namespace

void addDropCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("drop", "Mark a participant as dropped out (their slot is re-assigned to the next newcomer)");
  auto o = std::make_shared<DropOptions>();
  cmd->add_option("db", o->db, "study database")->required();
  cmd->add_option("--participant", o->participant, "participant id")->required();
  cmd->add_option("--reason", o->reason, "why (stored with the assignment)")->capture_default_str();
  cmd->add_option("--experiment", o->experiment, "experiment id (when the database holds several)");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
