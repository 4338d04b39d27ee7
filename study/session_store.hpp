#pragma once
// SessionStore: the study database (SQLite, WAL). Tables: experiments (file text, sha256, tlab
// version), participants, assignments (slot → design row; dropped rows are re-assigned),
// sessions, trials (the plan with stimulus path + sha256, condition, seed, question and truth),
// responses (raw answer, score, RT, monotonic timestamps; at most one per trial), events and
// questionnaire answers. The schema version is PRAGMA user_version. Every write that a
// participant's progress depends on is one transaction, committed before the runner goes on.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "study/counterbalancing.hpp"
#include "study/experiment.hpp"
#include "study/sqlite_database.hpp"

namespace tlab::study {

struct ParticipantRecord {
  std::int64_t id = 0;
  std::int64_t experiment = 0;  // the version row it enrolled under
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

// One version of an experiment file in the database: the same experiment id with another text
// (sha256) is a new version; every session records the version it ran.
struct ExperimentVersion {
  std::int64_t row = 0;
  std::string experimentId;
  int version = 1;
  std::string sha256;
  std::string filePath;
  std::string fileText;
};

// Another process is running this participant's session right now.
class SessionConflict : public StoreError {
 public:
  using StoreError::StoreError;
};

class SessionStore {
 public:
  static constexpr int kSchemaVersion = 3;  // = latestSchemaVersion() (study/schema_migrations.hpp)

  // Create/Write: opens (or creates) the file; refuses a file that is not SQLite, one with other
  // tables, a newer schema and a damaged file (PRAGMA quick_check) before anything is written;
  // then switches to WAL and migrates an older schema. Read: never writes a byte (see OpenMode);
  // an older schema is copied into memory and migrated there.
  explicit SessionStore(const std::string& path, OpenMode mode = OpenMode::Create);
  SessionStore(const std::string& path, bool create) : SessionStore(path, create ? OpenMode::Create : OpenMode::Write) {}

  Database& database() { return *db_; }
  const std::string& path() const { return path_; }

  // Versions of `experimentId`, oldest first; the version whose text is `experiment`'s, if stored.
  std::vector<ExperimentVersion> versions(const std::string& experimentId);
  std::optional<ExperimentVersion> findVersion(const Experiment& experiment);
  std::optional<std::int64_t> findExperiment(const std::string& experimentId);  // latest version's row

  // The participant under any version of the experiment.
  std::optional<ParticipantRecord> findParticipant(const std::string& experimentId, const std::string& participant);
  // The lowest free slot: never assigned, or freed by a dropout (over every version).
  int nextFreeSlot(const std::string& experimentId);
  // One transaction: this file's version (registered if new), the participant in `slot`, its
  // assignment and its whole plan. Writes nothing and returns nullopt when `slot` was taken in the
  // meantime (the caller prepares the plan of the new slot and tries again).
  std::optional<ParticipantRecord> enrol(const Experiment& experiment, const std::string& tlabVersion, const std::string& participant,
                                         int slot, const Design& design, const std::vector<TrialRecord>& trials);
  void dropParticipant(const std::string& experimentId, const std::string& participant, const std::string& reason);
  void finishParticipant(std::int64_t participantId);
  std::vector<AssignmentRecord> assignments(const std::string& experimentId);

  // One transaction: registers this file's version if new, refuses (SessionConflict) while
  // another live process runs a session of this participant, marks the participant's sessions
  // left open by a dead process as interrupted and resumed by the new one, and opens the session.
  std::int64_t startSession(std::int64_t participantId, const Experiment& experiment, const std::string& tlabVersion,
                            const std::string& mode);
  void endSession(std::int64_t session, const std::string& reason);

  // Stores the whole plan of a participant in one transaction (databases whose plan is missing).
  void insertTrials(std::int64_t participantId, const std::vector<TrialRecord>& trials);
  std::vector<TrialRecord> trials(std::int64_t participantId);
  // Seconds already used per trial key "phase/block/task/trial" (trial time limits continue).
  std::map<std::string, double> usedSeconds(std::int64_t participantId);

  // The stimulus of `trial` was shown: committed at once, before any answer. Returns how often
  // this trial has now been shown (2 and more: shown again after an interruption).
  int recordOnset(std::int64_t session, std::int64_t trial, std::int64_t tNs, const std::string& detail);
  // One transaction: the response and its event. Throws StoreError if the trial already has one.
  void recordResponse(const ResponseRecord& response);
  void recordEvent(std::int64_t session, std::optional<std::int64_t> trial, std::int64_t tNs, const std::string& kind,
                   const std::string& detail);
  // All items of one questionnaire screen in one transaction.
  void recordQuestionnaire(std::int64_t participantId, std::int64_t session, const std::string& questionnaire, int block,
                           const std::vector<std::pair<std::string, int>>& itemValues);
  bool hasQuestionnaireAnswers(std::int64_t participantId, const std::string& questionnaire, int block);

 private:
  int requireStudyDatabase();  // the schema version
  void checkIntegrity();
  ExperimentVersion ensureVersion(const Experiment& experiment, const std::string& tlabVersion);
  std::string path_;
  std::unique_ptr<Database> db_;
  int responses_ = 0;  // response transactions of this process (fault points)
};

// "host:pid" of this process, stored with each session (two stations may share one database).
std::string stationName();
// Whether the process of a session's station still runs: "alive" for this machine's live processes
// started at `processStart`, "dead" for this machine's others, "unknown" for another machine's.
std::string stationState(const std::string& station, const std::string& processStart);
// This process's start time (clock ticks since boot, /proc/self/stat), stored with each session.
std::string processStartTime();

// UTC now as "2026-11-21T23:59:59.123Z".
std::string utcTimestamp();

}  // namespace tlab::study
