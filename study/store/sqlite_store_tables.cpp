// SqliteStore: the tables that export and analysis read, through the SQL both stores share
// (study/store/store_tables.hpp) run on this store's file.
#include <sqlite3.h>

#include "study/store/sqlite_store.hpp"
#include "study/store/store_tables.hpp"

namespace tlab::study {

namespace {

class SqliteRow : public ResultRow {
 public:
  explicit SqliteRow(const Statement& s) : s_(s) {}
  bool isNull(int column) const override { return s_.isNull(column); }
  std::int64_t integer(int column) const override { return s_.integer(column); }
  double real(int column) const override { return s_.real(column); }
  std::string text(int column) const override { return s_.text(column); }

 private:
  const Statement& s_;
};

class SqliteQueries : public TableQueries {
 public:
  explicit SqliteQueries(Database& db) : db_(db) {}
  void forEachRow(const std::string& sql, const std::string& parameter, const std::function<void(const ResultRow&)>& row) override {
    Statement s = db_.prepare(sql);
    if (sql.find("?1") != std::string::npos) s.bind(1, parameter);
    const SqliteRow view(s);
    while (s.step()) row(view);
  }

 private:
  Database& db_;
};

}  // namespace

DataTable SqliteStore::exportTable(ExportTable table, const Experiment& e) {
  SqliteQueries q(*db_);
  return store_tables::exportTable(q, table, e);
}

std::vector<AnalysisRecord> SqliteStore::analysisRecords(const std::string& experimentId, const std::string& dv) {
  SqliteQueries q(*db_);
  return store_tables::analysisRecords(q, experimentId, dv);
}

std::vector<std::map<std::string, int>> SqliteStore::sessionModes(const std::string& experimentId) {
  SqliteQueries q(*db_);
  return store_tables::sessionModes(q, experimentId);
}

std::vector<StoredAnswer> SqliteStore::formAnswers(const std::string& experimentId) {
  SqliteQueries q(*db_);
  return store_tables::formAnswers(q, experimentId);
}

DataTable SqliteStore::stimulusSummary(const std::string& experimentId) {
  SqliteQueries q(*db_);
  return store_tables::stimulusSummary(q, experimentId);
}

DataTable SqliteStore::stimulusExamples(const std::string& experimentId) {
  SqliteQueries q(*db_);
  return store_tables::stimulusExamples(q, experimentId);
}

DataTable SqliteStore::liveTrials(const std::string& experimentId) {
  SqliteQueries q(*db_);
  return store_tables::liveTrials(q, experimentId);
}

DataTable SqliteStore::trialFrames(std::int64_t trial) {
  SqliteQueries q(*db_);
  return store_tables::trialFrames(q, trial);
}

}  // namespace tlab::study
