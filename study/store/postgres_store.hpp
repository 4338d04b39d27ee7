#pragma once
// PostgresStore: the Store on a PostgreSQL server (libpqxx), for studies that outgrow one machine:
// many stations and server threads write one database at once. The same tables, columns and export
// tables as SqliteStore (study/store/postgres_schema.cpp). Every write is one transaction; slots go
// to one participant each (enrolment holds a per-experiment lock), a trial takes one response
// (a unique constraint), and a session of a live station is refused (SessionConflict). A lost
// connection fails the call that needed it and the next call connects again. Threads may share a
// store (calls take turns on its one connection); for calls in parallel, open a store per thread.
#include <memory>

#include "study/store/store.hpp"

namespace tlab::study {

class PostgresConnection;
class PgTransaction;

class PostgresStore : public Store {
 public:
  // `url`: postgresql://[user[:password]@][host][:port]/dbname[?param=value&...] (libpq's syntax).
  // Create/Write: creates the tables in an empty database. Read: never changes the database (the
  // connection's transactions are read-only on the server). Refuses a database with other tables
  // or a newer schema, and an unreachable server, with one line (StoreError).
  explicit PostgresStore(const std::string& url, OpenMode mode = OpenMode::Create);
  ~PostgresStore() override;

  // The URL without its password.
  const std::string& location() const override;

  // The Store (study/store/store.hpp documents each).
  std::vector<std::string> experimentIds() override;
  std::vector<ExperimentVersion> versions(const std::string& experimentId) override;
  std::optional<ExperimentVersion> findVersion(const Experiment& experiment) override;
  std::optional<std::int64_t> findExperiment(const std::string& experimentId) override;
  int sessionCount(std::int64_t versionRow) override;
  std::optional<ParticipantRecord> findParticipant(const std::string& experimentId, const std::string& participant) override;
  int nextFreeSlot(const std::string& experimentId) override;
  std::optional<ParticipantRecord> enrol(const Experiment& experiment, const std::string& tlabVersion, const std::string& participant,
                                         int slot, const Design& design, const std::vector<TrialRecord>& trials) override;
  void dropParticipant(const std::string& experimentId, const std::string& participant, const std::string& reason) override;
  void finishParticipant(std::int64_t participantId) override;
  std::vector<AssignmentRecord> assignments(const std::string& experimentId) override;
  std::int64_t startSession(std::int64_t participantId, const Experiment& experiment, const std::string& tlabVersion,
                            const std::string& mode) override;
  void endSession(std::int64_t session, const std::string& reason) override;
  void insertTrials(std::int64_t participantId, const std::vector<TrialRecord>& trials) override;
  std::vector<TrialRecord> trials(std::int64_t participantId) override;
  std::map<std::string, double> usedSeconds(std::int64_t participantId) override;
  int recordOnset(std::int64_t session, std::int64_t trial, std::int64_t tNs, const std::string& detail) override;
  void recordResponse(const ResponseRecord& response) override;
  void recordEvent(std::int64_t session, std::optional<std::int64_t> trial, std::int64_t tNs, const std::string& kind,
                   const std::string& detail) override;
  void recordEvents(std::int64_t session, std::optional<std::int64_t> trial, const std::vector<EventRecord>& events) override;
  void recordQuestionnaire(std::int64_t participantId, std::int64_t session, const std::string& questionnaire, int block,
                           const std::vector<FormAnswer>& answers) override;
  bool hasQuestionnaireAnswers(std::int64_t participantId, const std::string& questionnaire, int block) override;
  void recordDecline(const Experiment& experiment, const std::string& tlabVersion, const std::string& participant) override;
  void recordConsent(std::int64_t participantId, std::int64_t session, bool accepted) override;
  bool hasConsent(std::int64_t participantId) override;
  std::optional<std::string> lastEventDetail(std::int64_t participantId, const std::string& kind) override;
  void recordInfo(std::int64_t participantId, std::int64_t session, const std::vector<FormAnswer>& answers) override;
  bool hasInfo(std::int64_t participantId) override;
  void recordDisplay(std::int64_t session, const std::string& displayJson) override;
  // The tables both stores share (study/store/store_tables.hpp), in one read-only transaction each.
  DataTable exportTable(ExportTable table, const Experiment& experiment) override;
  std::vector<AnalysisRecord> analysisRecords(const std::string& experimentId, const std::string& dependentVariable) override;
  std::vector<std::map<std::string, int>> sessionModes(const std::string& experimentId) override;
  std::vector<StoredAnswer> formAnswers(const std::string& experimentId) override;
  DataTable stimulusSummary(const std::string& experimentId) override;
  DataTable stimulusExamples(const std::string& experimentId) override;
  DataTable liveTrials(const std::string& experimentId) override;
  DataTable trialFrames(std::int64_t trial) override;

 private:
  bool exists(const std::string& sql, const std::vector<std::optional<std::string>>& params);
  std::unique_ptr<PostgresConnection> connection_;
  int responses_ = 0;  // response transactions of this process (fault points)
};

}  // namespace tlab::study
