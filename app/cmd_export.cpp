// tlab export study.db --csv DIR: tidy long-format CSV files (trials, questionnaires,
// participants, events) that R and pandas read as is.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.hpp"
#include "study/csv_export.hpp"

namespace tlab::app {

namespace {

struct ExportOptions {
  std::string db;
  std::string csv;
  std::string experiment;
};

void run(const ExportOptions& o) {
  if (!std::filesystem::exists(o.db)) throw std::runtime_error(o.db + ": no such database");
  study::SessionStore store(o.db, false);
  const study::StoredExperiment stored = study::storedExperiment(store, o.experiment);
  for (const auto& path : study::exportCsv(store, stored, o.csv)) std::printf("wrote %s\n", path.c_str());
}

}  // namespace

void addExportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("export", "Export a study database as tidy long-format CSV");
  auto o = std::make_shared<ExportOptions>();
  cmd->add_option("db", o->db, "study database")->required();
  cmd->add_option("--csv", o->csv, "output folder for the CSV files")->required();
  cmd->add_option("--experiment", o->experiment, "experiment id (when the database holds several)");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
