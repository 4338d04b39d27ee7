#pragma once
// Store: everything the study needs from storage, behind one interface — experiment versions,
// counterbalancing slots, sessions, the plan, onsets, responses, events and questionnaire answers,
// and the tables that export and analysis read. study/ code sees only this interface and never an
// SQL statement or a database handle; SqliteStore (study/store/sqlite_store.hpp) implements it on one
// SQLite file, PostgresStore (study/store/postgres_store.hpp) on a PostgreSQL server. Every write a participant's progress depends on is one transaction, committed
// before the runner goes on.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/design/counterbalancing.hpp"
#include "study/design/experiment.hpp"
#include "study/store/store_basics.hpp"

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
  // Frame timing (window sessions): the swap-to-swap interval of the onset frame, the frames of
  // the trial whose interval exceeded 1.5 refresh intervals, and stimulus request to swap.
  std::optional<double> onsetFrameMs;
  std::optional<int> lateFrames;
  std::optional<double> onsetToSwapMs;
};

// One event of a session (an onset's details, a drag, a shown frame, ...): the monotonic time, its
// kind and its detail (JSON or text).
struct EventRecord {
  std::int64_t tNs = 0;
  std::string kind;
  std::string detail;
};

// One answer of a form (participant information or a questionnaire): the text as given and its
// number where it has one (study/design/form_field.hpp).
struct FormAnswer {
  std::string field;
  std::string value;
  std::optional<double> number;
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

// A table for export or analysis: a header and rows of text cells ("" for missing values;
// numbers written with 17 significant digits, so they read back exactly).
struct DataTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

// The tidy tables a store exports (study/store/csv_export.hpp documents each).
enum class ExportTable { Trials, Sessions, Questionnaires, Participants, Events, Info, Consent };

// One answered-or-missing test record for the analysis table of one dependent variable.
struct AnalysisRecord {
  std::string participant;
  std::string levelsJson;
  std::string taskId;
  int block = 0;
  double value = 0.0;
  std::size_t sourceRow = 0;  // the trial's id, for messages
  std::string stimulusSha256;  // the image shown: the stimulus of a mixed model's (1 | stimulus)
};

// One stored form answer, for report summaries.
struct StoredAnswer {
  std::string participant;
  std::string form;  // questionnaire id, or "info"
  std::string field;
  std::string value;
  std::optional<double> number;
  std::size_t sourceRow = 0;
};

class Store {
 public:
  virtual ~Store() = default;
  // Where the store is (a file path or a server URL), for messages.
  virtual const std::string& location() const = 0;

  // Experiment ids in the order they first appeared; versions of one id, oldest first.
  virtual std::vector<std::string> experimentIds() = 0;
  virtual std::vector<ExperimentVersion> versions(const std::string& experimentId) = 0;
  // The version whose text is `experiment`'s, if stored.
  virtual std::optional<ExperimentVersion> findVersion(const Experiment& experiment) = 0;
  virtual std::optional<std::int64_t> findExperiment(const std::string& experimentId) = 0;  // newest version's row
  virtual int sessionCount(std::int64_t versionRow) = 0;

  // The participant under any version of the experiment.
  virtual std::optional<ParticipantRecord> findParticipant(const std::string& experimentId, const std::string& participant) = 0;
  // The lowest free slot: never assigned, or freed by a dropout (over every version).
  virtual int nextFreeSlot(const std::string& experimentId) = 0;
  // One transaction: this file's version (registered if new), the participant in `slot`, its
  // assignment and its whole plan. Writes nothing and returns nullopt when `slot` was taken in the
  // meantime (the caller prepares the plan of the new slot and tries again).
  virtual std::optional<ParticipantRecord> enrol(const Experiment& experiment, const std::string& tlabVersion,
                                                 const std::string& participant, int slot, const Design& design,
                                                 const std::vector<TrialRecord>& trials) = 0;
  virtual void dropParticipant(const std::string& experimentId, const std::string& participant, const std::string& reason) = 0;
  virtual void finishParticipant(std::int64_t participantId) = 0;
  virtual std::vector<AssignmentRecord> assignments(const std::string& experimentId) = 0;

  // One transaction: registers this file's version if new, refuses (SessionConflict) while
  // another live process runs a session of this participant, marks the participant's sessions
  // left open by a dead process as interrupted and resumed by the new one, and opens the session.
  virtual std::int64_t startSession(std::int64_t participantId, const Experiment& experiment, const std::string& tlabVersion,
                                    const std::string& mode) = 0;
  virtual void endSession(std::int64_t session, const std::string& reason) = 0;

  // Stores the whole plan of a participant in one transaction (databases whose plan is missing).
  virtual void insertTrials(std::int64_t participantId, const std::vector<TrialRecord>& trials) = 0;
  virtual std::vector<TrialRecord> trials(std::int64_t participantId) = 0;
  // Seconds already used per trial key "phase/block/task/trial" (trial time limits continue).
  virtual std::map<std::string, double> usedSeconds(std::int64_t participantId) = 0;

  // The stimulus of `trial` was shown: committed at once, before any answer. Returns how often
  // this trial has now been shown (2 and more: shown again after an interruption).
  virtual int recordOnset(std::int64_t session, std::int64_t trial, std::int64_t tNs, const std::string& detail) = 0;
  // One transaction: the response and its event. Throws StoreError if the trial already has one.
  virtual void recordResponse(const ResponseRecord& response) = 0;
  virtual void recordEvent(std::int64_t session, std::optional<std::int64_t> trial, std::int64_t tNs, const std::string& kind,
                           const std::string& detail) = 0;
  // Several events in one transaction, in order (a live trial's frames: one commit, not one each).
  virtual void recordEvents(std::int64_t session, std::optional<std::int64_t> trial, const std::vector<EventRecord>& events) = 0;
  // All items of one questionnaire screen in one transaction.
  virtual void recordQuestionnaire(std::int64_t participantId, std::int64_t session, const std::string& questionnaire, int block,
                                   const std::vector<FormAnswer>& answers) = 0;
  virtual bool hasQuestionnaireAnswers(std::int64_t participantId, const std::string& questionnaire, int block) = 0;

  // A newcomer who declined consent: only that is stored (the version, the participant with
  // status "declined", no slot, and the decision). Later runs of that id are refused.
  virtual void recordDecline(const Experiment& experiment, const std::string& tlabVersion, const std::string& participant) = 0;
  virtual void recordConsent(std::int64_t participantId, std::int64_t session, bool accepted) = 0;
  virtual bool hasConsent(std::int64_t participantId) = 0;
  // The detail of this participant's newest event of `kind` over all their sessions (a returning
  // participant's size calibration is not asked again, even after a server restart).
  virtual std::optional<std::string> lastEventDetail(std::int64_t participantId, const std::string& kind) = 0;
  // Participant information, all fields in one transaction.
  virtual void recordInfo(std::int64_t participantId, std::int64_t session, const std::vector<FormAnswer>& answers) = 0;
  virtual bool hasInfo(std::int64_t participantId) = 0;
  // The display a session runs on (GL renderer, sizes, refresh rate, swap interval), as JSON.
  virtual void recordDisplay(std::int64_t session, const std::string& displayJson) = 0;

  // The rows of one export table for every version of `experiment`'s id (one column per factor
  // of `experiment` in the trials table).
  virtual DataTable exportTable(ExportTable table, const Experiment& experiment) = 0;
  // Test records of non-dropped participants with a value of `dependentVariable` (correct, score,
  // rt, error, partial_credit, answered), in participant and sequence order.
  virtual std::vector<AnalysisRecord> analysisRecords(const std::string& experimentId, const std::string& dependentVariable) = 0;
  // Per participant with sessions: how many of their sessions ran in each mode ("simulated", ...).
  virtual std::vector<std::map<std::string, int>> sessionModes(const std::string& experimentId) = 0;
  // Questionnaire answers ("info": participant information) of non-dropped participants, in order.
  virtual std::vector<StoredAnswer> formAnswers(const std::string& experimentId) = 0;
  // The stimuli shown: condition, task, phase, stimulus key, file, sha256, trials, participants
  // (test before training); and the file of the first test question of each condition and task.
  virtual DataTable stimulusSummary(const std::string& experimentId) = 0;
  virtual DataTable stimulusExamples(const std::string& experimentId) = 0;
  // The interactive trials with live frames stored ("frame" events, study/run/frame_log.hpp):
  // participant, sequence, phase, task_id, frames, in participant and sequence order.
  virtual DataTable liveTrials(const std::string& experimentId) = 0;
  // The "frame" events of one trial (TrialRecord::id) in the order stored: session, t_ns, detail.
  virtual DataTable trialFrames(std::int64_t trial) = 0;
};

// "host:pid" of this process, stored with each session (two stations may share one database).
std::string stationName();
// Whether the process of a session's station still runs: "alive" for this machine's live processes
// started at `processStart`, "dead" for this machine's others, "unknown" for another machine's.
std::string stationState(const std::string& station, const std::string& processStart);
// What an open session of this participant means to a new one: stationState(), except that a
// session of this very process is "dead" — a process walks one flow per participant at a time, so
// a session it left open (its flow stopped on a storage error) has ended. startSession uses it.
std::string openSessionState(const std::string& station, const std::string& processStart);
// This process's start time (clock ticks since boot, /proc/self/stat), stored with each session.
std::string processStartTime();

// UTC now as "2026-11-21T23:59:59.123Z".
std::string utcTimestamp();

}  // namespace tlab::study
