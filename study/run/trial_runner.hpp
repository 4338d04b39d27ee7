#pragma once
// TrialRunner: runs one participant's session — enrolment (or resumption), the plan stored in the
// database before the first stimulus, welcome and task instructions, training and test trials in
// the plan's order with their time limits, questionnaires, and the end. Each response is scored
// by its task and committed in its own transaction before the next stimulus is prepared, so a
// crash loses at most the trial on screen; --resume continues at the first unanswered trial.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "renderer/scene/builtin_scenes.hpp"
#include "study/design/counterbalancing.hpp"
#include "study/design/experiment.hpp"
#include "study/run/responder.hpp"
#include "study/design/session_plan.hpp"
#include "study/store/store.hpp"
#include "tasks/task.hpp"
#include "study/run/stimulus_library.hpp"

namespace tlab::study {

struct RunOptions {
  std::string participant;
  bool resume = false;
  std::string tlabVersion = "unknown";
};

// One committed response, for progress lines.
struct TrialProgress {
  std::string participant;
  int index = 0;  // 1-based sequence
  int total = 0;
  const PlannedTrial* plan = nullptr;
  std::optional<std::string> answer;
  bool correct = false;
  std::optional<double> rtSeconds;
};

enum class SessionOutcome { Finished, Closed, Declined };

struct SessionResult {
  SessionOutcome outcome = SessionOutcome::Finished;
  int slot = 0;
  int answeredBefore = 0;  // responses already stored when this run started (resume)
  int answeredNow = 0;
  int total = 0;
};

class TrialRunner {
 public:
  TrialRunner(const Experiment& experiment, Store& store, StimulusSource& stimuli);

  void onProgress(std::function<void(const TrialProgress&)> callback) { progress_ = std::move(callback); }

  // Throws StoreError as checkParticipant() does.
  SessionResult run(const RunOptions& options, Responder& responder);

 private:
  struct Session;
  bool runTrial(Session& s, std::size_t index);
  ResponseRecord scoreResponse(const Session& s, const TrialRecord& record, const PreparedTrial& prepared, const Response& response,
                               double limit, tasks::Score& score) const;
  std::string participantTitle() const;
  std::optional<SessionOutcome> greetNewcomer(const RunOptions& options, Responder& responder);
  std::optional<SessionOutcome> openSession(Session& s, bool newcomer);
  bool betweenTrials(Session& s, std::size_t done);
  bool runQuestionnaires(Session& s, const std::string& when, int block);
  void storeEvents(Session& s, std::optional<std::int64_t> trial);
  // Ends the session as far as the store still allows and throws a StoreError naming the trial
  // that was not stored and how many acknowledged responses are safe.
  [[noreturn]] void stopAfterStorageError(Session& s, const SessionResult& result, std::size_t index, const StoreError& e);

  struct Newcomer {
    int slot = 0;
    SessionPlan plan;
    std::vector<TrialRecord> records;
  };
  std::vector<TrialRecord> preparePlan(const SessionPlan& plan);
  std::optional<SessionOutcome> admit(const RunOptions& options, Responder& responder,
                                      const std::optional<ParticipantRecord>& existing, ParticipantRecord& participant,
                                      SessionPlan& plan);
  std::vector<TrialRecord> storedPlan(const RunOptions& options, const ParticipantRecord& participant, const SessionPlan& plan);
  SessionOutcome runTrials(Session& s, std::size_t first, SessionResult& result);
  Newcomer prepareNewcomer();
  ParticipantRecord enrolNewcomer(const RunOptions& options, Newcomer& newcomer);

  const Experiment& experiment_;
  Store& store_;
  StimulusSource& stimuli_;
  Design design_;
  std::function<void(const TrialProgress&)> progress_;
  int sessions_ = 0, onsets_ = 0, acks_ = 0;  // counts of this process (fault points)
};

// Throws StoreError with a clear message when the participant has finished, has dropped out, has
// an unfinished session without `resume`, or has none to resume. TrialRunner::run checks this
// too; calling it first lets a command refuse before it opens a window.
void checkParticipant(Store& store, const Experiment& experiment, const RunOptions& options);

// The database record of a planned and prepared trial.
TrialRecord makeTrialRecord(const PlannedTrial& plan, const PreparedTrial& prepared);

}  // namespace tlab::study
