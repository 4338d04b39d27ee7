// PostgresStore: the tables that export and analysis read, through the SQL both stores share
// (study/store/store_tables.hpp), each in one read-only transaction (one snapshot).
#include "study/store/postgres_connection.hpp"
#include "study/store/postgres_store.hpp"

namespace tlab::study {

DataTable PostgresStore::exportTable(ExportTable table, const Experiment& e) {
  DataTable out;
  connection_->read([&](PgTransaction& t) { out = store_tables::exportTable(t.tables(), table, e); });
  return out;
}

std::vector<AnalysisRecord> PostgresStore::analysisRecords(const std::string& experimentId, const std::string& dv) {
  std::vector<AnalysisRecord> out;
  connection_->read([&](PgTransaction& t) { out = store_tables::analysisRecords(t.tables(), experimentId, dv); });
  return out;
}

std::vector<std::map<std::string, int>> PostgresStore::sessionModes(const std::string& experimentId) {
  std::vector<std::map<std::string, int>> out;
  connection_->read([&](PgTransaction& t) { out = store_tables::sessionModes(t.tables(), experimentId); });
  return out;
}

std::vector<StoredAnswer> PostgresStore::formAnswers(const std::string& experimentId) {
  std::vector<StoredAnswer> out;
  connection_->read([&](PgTransaction& t) { out = store_tables::formAnswers(t.tables(), experimentId); });
  return out;
}

DataTable PostgresStore::stimulusSummary(const std::string& experimentId) {
  DataTable out;
  connection_->read([&](PgTransaction& t) { out = store_tables::stimulusSummary(t.tables(), experimentId); });
  return out;
}

DataTable PostgresStore::stimulusExamples(const std::string& experimentId) {
  DataTable out;
  connection_->read([&](PgTransaction& t) { out = store_tables::stimulusExamples(t.tables(), experimentId); });
  return out;
}

DataTable PostgresStore::liveTrials(const std::string& experimentId) {
  DataTable out;
  connection_->read([&](PgTransaction& t) { out = store_tables::liveTrials(t.tables(), experimentId); });
  return out;
}

DataTable PostgresStore::trialFrames(std::int64_t trial) {
  DataTable out;
  connection_->read([&](PgTransaction& t) { out = store_tables::trialFrames(t.tables(), trial); });
  return out;
}

}  // namespace tlab::study
