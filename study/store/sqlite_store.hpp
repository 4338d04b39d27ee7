#pragma once
// SqliteStore: the Store on one SQLite file (WAL). Tables: experiments (one row per version of an
// experiment file: text, sha256, tlab version), participants, assignments (slot → design row;
// dropped rows are re-assigned), sessions (version, station, how they ended), trials (the plan with
// stimulus path + sha256, condition, seed, question and truth), responses (raw answer, score, RT,
// monotonic timestamps; at most one per trial), events (onsets, responses, camera moves, pauses)
// and questionnaire answers. The schema version is PRAGMA user_version (study/schema_migrations).
#include <memory>

#include "study/store/sqlite_database.hpp"
#include "study/store/store.hpp"

namespace tlab::study {

class SqliteStore : public Store {
 public:
  static constexpr int kSchemaVersion = 4;  // = latestSchemaVersion() (study/store/schema_migrations.hpp)

  // Create/Write: opens (or creates) the file; refuses a file that is not SQLite, one with other
  // tables, a newer schema and a damaged file (PRAGMA quick_check) before anything is written;
  // then switches to WAL and migrates an older schema. Read: never writes a byte (see OpenMode);
  // an older schema is copied into memory and migrated there.
  explicit SqliteStore(const std::string& path, OpenMode mode = OpenMode::Create);
  // A file this store created is removed again when the store is destroyed by an exception (a
  // start that failed) while it holds no experiment: a failed start leaves no empty database
  // behind (a rerun would refuse it as "already holds a study"). Anything stored is kept.
  ~SqliteStore() override;
  SqliteStore(const SqliteStore&) = delete;
  SqliteStore& operator=(const SqliteStore&) = delete;

  const std::string& location() const override { return path_; }

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
  DataTable exportTable(ExportTable table, const Experiment& experiment) override;  // study/store/store_tables.cpp
  std::vector<AnalysisRecord> analysisRecords(const std::string& experimentId, const std::string& dependentVariable) override;
  std::vector<std::map<std::string, int>> sessionModes(const std::string& experimentId) override;
  std::vector<StoredAnswer> formAnswers(const std::string& experimentId) override;
  DataTable stimulusSummary(const std::string& experimentId) override;
  DataTable stimulusExamples(const std::string& experimentId) override;
  DataTable liveTrials(const std::string& experimentId) override;
  DataTable trialFrames(std::int64_t trial) override;

 private:
  int requireStudyDatabase();  // the schema version
  void checkIntegrity();
  ExperimentVersion ensureVersion(const Experiment& experiment, const std::string& tlabVersion);
  std::string path_;
  bool created_ = false;        // the file did not exist before this store opened it for writing
  int unwindingAtOpen_ = 0;     // std::uncaught_exceptions() when opened
  std::unique_ptr<Database> db_;
  int responses_ = 0;  // response transactions of this process (fault points)
};

}  // namespace tlab::study
