// tlab export study.db --csv DIR: tidy long-format CSV files (trials, questionnaires,
// participants, events) that R and pandas read as is.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.hpp"
#include "study/store/csv_export.hpp"
#include "study/store/open_store.hpp"

namespace tlab::app {

namespace {

struct ExportOptions {
  std::string db;
  std::string csv;
  std::string experiment;
  bool poolVersions = false;
};

void run(const ExportOptions& o) {
  const auto storeOwner = study::openStore(o.db, study::OpenMode::Read);
  study::Store& store = *storeOwner;
  const study::StoredExperiment stored = study::storedExperiment(store, o.experiment, o.poolVersions);
  std::printf("experiment '%s': data from %s\n", stored.experiment.id.c_str(), stored.describeVersions().c_str());
  for (const auto& path : study::exportCsv(store, stored, o.csv)) std::printf("wrote %s\n", path.c_str());
}

}  // namespace

void addExportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("export", "Export a study database as tidy long-format CSV");
  auto o = std::make_shared<ExportOptions>();
  cmd->add_option("db", o->db, "study database")->required();
  cmd->add_option("--csv", o->csv, "output folder for the CSV files")->required();
  cmd->add_option("--experiment", o->experiment, "experiment id (when the database holds several)");
  cmd->add_flag("--pool-versions", o->poolVersions, "export data of experiment versions whose designs differ together");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
