#pragma once
// SessionStore: the study database (SQLite, WAL). Tables: experiments (file text, sha256, tlab
// version), participants, assignments (slot → design row; dropped rows are re-assigned),
// sessions, trials (the plan with stimulus path + sha256, condition, seed, question and truth),
// responses (raw answer, score, RT, monotonic timestamps; at most one per trial), events and
// questionnaire answers. The schema version is PRAGMA user_version. Every write that a
// participant's progress depends on is one transaction, committed before the runner goes on.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "study/counterbalancing.hpp"
#include "study/experiment.hpp"
#include "study/sqlite_database.hpp"

namespace tlab::study {

struct ParticipantRecord {
  std::int64_t id = 0;
  std::string participant;
  int slot = 0;
  std::string status;  // active, finished, dropped
};

struct AssignmentRecord {
  int slot = 0;
  int row = 0;
  int betweenCell = 0;
  std::string participant;
  std::string status;  // active, finished, dropped
  std::string blockOrder;
};

struct TrialRecord {
  std::int64_t id = 0;
  int sequence = 0;
  std::string phase;
  int block = 0;
  std::string condition;
  std::string levelsJson;
  std::string taskId;
  std::string task;
  int trial = 1;
  int question = 1;
  int questionsInTrial = 1;
  std::string stimulusKey;
  std::uint64_t probeSeed = 0;
  std::string questionJson;
  std::string answerKind;
  std::string truthJson;
  double timeLimitSeconds = 0.0;
  std::optional<double> trialTimeLimitSeconds;
  std::string stimulusPath;
  std::string stimulusSha256;
  bool answered = false;  // a response row exists
};

struct ResponseRecord {
  std::int64_t trial = 0;
  std::int64_t session = 0;
  std::optional<std::string> rawAnswer;  // nullopt: missing
  bool answered = false;
  bool correct = false;
  double score = 0.0;
  std::optional<double> partialCredit;
  std::optional<double> error;
  std::optional<double> rtSeconds;
  std::int64_t onsetNs = 0;     // monotonic clock at the stimulus onset (buffer swap)
  std::int64_t responseNs = 0;  // monotonic clock at the response
  std::string note;
};

class SessionStore {
 public:
  static constexpr int kSchemaVersion = 2;  // = latestSchemaVersion() (study/schema_migrations.hpp)

  // Opens or creates the database file; refuses a newer or foreign schema and a damaged file
  // (PRAGMA quick_check); migrates an older schema (a reader of a read-only file goes without).
  explicit SessionStore(const std::string& path, bool create = true);

  Database& database() { return db_; }

  // The experiments row for this file (inserted on first use). Throws when the database already
  // holds the same experiment id with a different file text.
  std::int64_t registerExperiment(const Experiment& experiment, const std::string& tlabVersion);
  std::optional<std::int64_t> findExperiment(const std::string& experimentId);

  std::optional<ParticipantRecord> findParticipant(std::int64_t experiment, const std::string& participant);
  // A new participant takes the lowest free slot: never assigned, or freed by a dropout.
  ParticipantRecord enrol(std::int64_t experiment, const std::string& participant, const Design& design);
  void dropParticipant(std::int64_t experiment, const std::string& participant, const std::string& reason);
  void finishParticipant(std::int64_t participantId);
  std::vector<AssignmentRecord> assignments(std::int64_t experiment);

  std::int64_t startSession(std::int64_t participantId, const std::string& mode);
  void endSession(std::int64_t session, const std::string& reason);

  // Stores the whole plan of a participant in one transaction (before the first trial shows).
  void insertTrials(std::int64_t participantId, const std::vector<TrialRecord>& trials);
  std::vector<TrialRecord> trials(std::int64_t participantId);

  // One transaction: the response and its event. Throws StoreError if the trial already has one.
  void recordResponse(const ResponseRecord& response);
  void recordEvent(std::int64_t session, std::optional<std::int64_t> trial, std::int64_t tNs, const std::string& kind,
                   const std::string& detail);
  // All items of one questionnaire screen in one transaction.
  void recordQuestionnaire(std::int64_t participantId, std::int64_t session, const std::string& questionnaire, int block,
                           const std::vector<std::pair<std::string, int>>& itemValues);
  bool hasQuestionnaireAnswers(std::int64_t participantId, const std::string& questionnaire, int block);

 private:
  void checkIntegrity();
  Database db_;
};

// "host:pid" of this process, stored with each session (two stations may share one database).
std::string stationName();

// UTC now as "2026-11-21T23:59:59.123Z".
std::string utcTimestamp();

}  // namespace tlab::study
