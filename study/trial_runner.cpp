#include "study/trial_runner.hpp"

#include <map>

#include <nlohmann/json.hpp>

#include "study/fault_point.hpp"
#include "study/session_plan.hpp"
#include "tasks/answer_parser.hpp"
#include "tasks/question_json.hpp"
#include "tasks/task_registry.hpp"

namespace tlab::study {

struct TrialRunner::Session {
  Responder& responder;
  ParticipantRecord participant;
  std::int64_t session = 0;
  SessionPlan plan;
  std::vector<TrialRecord> stored;
  std::map<std::string, double> usedSeconds;  // trial key → seconds spent on its answered questions
  std::string lastTask;
};

namespace {

std::string trialKey(const PlannedTrial& p) {
  return std::string(phaseName(p.phase)) + "/" + std::to_string(p.block) + "/" + p.taskId + "/" + std::to_string(p.trial);
}

std::string levelsJson(const PlannedTrial& p) { return nlohmann::json(p.levels).dump(); }

}  // namespace

TrialRecord makeTrialRecord(const PlannedTrial& plan, const PreparedTrial& prepared) {
  TrialRecord r;
  r.sequence = plan.sequence;
  r.phase = phaseName(plan.phase);
  r.block = plan.block;
  r.condition = plan.condition;
  r.levelsJson = levelsJson(plan);
  r.taskId = plan.taskId;
  r.task = plan.task;
  r.trial = plan.trial;
  r.question = plan.question;
  r.questionsInTrial = plan.questionsInTrial;
  r.stimulusKey = plan.stimulus.text();
  r.probeSeed = plan.probeSeed;
  r.questionJson = tasks::toJson(prepared.question).dump();
  r.answerKind = tasks::answerKindName(prepared.question.answerKind);
  r.truthJson = tasks::groundTruthJson(prepared.question.truth).dump();
  r.timeLimitSeconds = plan.timeLimitSeconds;
  r.trialTimeLimitSeconds = plan.trialTimeLimitSeconds;
  r.stimulusPath = prepared.stimulusPath;
  r.stimulusSha256 = prepared.stimulusSha256;
  return r;
}

TrialRunner::TrialRunner(const Experiment& experiment, Store& store, StimulusLibrary& stimuli)
    : experiment_(experiment), store_(store), stimuli_(stimuli), design_(makeDesign(experiment)) {}

void TrialRunner::storeEvents(Session& s, std::optional<std::int64_t> trial) {
  for (const auto& e : s.responder.takeEvents()) store_.recordEvent(s.session, trial, e.tNs, e.kind, e.detail);
}

bool TrialRunner::runQuestionnaires(Session& s, const std::string& when, int block) {
  for (const auto& q : experiment_.questionnaires) {
    if (q.when != when || store_.hasQuestionnaireAnswers(s.participant.id, q.id, block)) continue;
    const auto values = s.responder.answerQuestionnaire(q);
    storeEvents(s, std::nullopt);
    if (!values) return false;
    std::vector<std::pair<std::string, int>> items;
    for (std::size_t i = 0; i < q.items.size(); ++i) items.emplace_back(q.items[i].id, values->at(i));
    store_.recordQuestionnaire(s.participant.id, s.session, q.id, block, items);
  }
  return true;
}

bool TrialRunner::runTrial(Session& s, std::size_t index) {
  const PlannedTrial& plan = s.plan.trials[index];
  const TrialRecord& record = s.stored[index];
  const PreparedTrial prepared = stimuli_.prepare(plan);
  if (prepared.stimulusSha256 != record.stimulusSha256)
    throw StoreError("trial " + std::to_string(plan.sequence) + ": the stimulus differs from the one stored when the session began "
                     "(sha256 " + prepared.stimulusSha256.substr(0, 12) + " vs " + record.stimulusSha256.substr(0, 12) + ")");
  const TaskSpec* spec = experiment_.task(plan.taskId);
  if (plan.taskId != s.lastTask) {
    const std::string title = plan.phase == Phase::Training ? "Training: " + plan.taskId : "Task: " + plan.taskId;
    if (!s.responder.showMessage(title, spec->instructions.empty() ? prepared.question.text : spec->instructions)) return false;
    s.lastTask = plan.taskId;
  }
  double limit = plan.timeLimitSeconds;
  const std::string key = trialKey(plan);
  if (plan.trialTimeLimitSeconds) limit = std::min(limit, *plan.trialTimeLimitSeconds - s.usedSeconds[key]);

  Response response;
  if (limit <= 0.0) {
    response.note = "trial time limit reached";  // never shown: missing, which counts as wrong
  } else {
    TrialView view{plan, prepared, limit, plan.sequence, int(s.plan.trials.size())};
    view.onset = [&](std::int64_t tNs, const std::string& detail) {
      store_.recordOnset(s.session, record.id, tNs, detail);
      faultPoint("onset", ++onsets_);
    };
    const auto given = s.responder.respond(view);
    storeEvents(s, record.id);
    if (!given) return false;
    response = *given;
  }
  tasks::Answer answer{response.text, response.rtSeconds};
  if (answer.text && answer.seconds && *answer.seconds > limit) answer.text.reset();  // over the limit: missing
  const auto task = tasks::makeTask(plan.task);
  tasks::Score score;
  try {
    score = task->score(prepared.question, answer);
  } catch (const tasks::AnswerFormatError& e) {
    score.answered = true;
    score.rawAnswer = *response.text;
    score.note = std::string("malformed: ") + e.what();
  }
  ResponseRecord r;
  r.trial = record.id;
  r.session = s.session;
  r.rawAnswer = response.text;
  r.answered = score.answered;
  r.correct = score.correct;
  r.score = score.value;
  r.partialCredit = score.partialCredit;
  r.error = score.error;
  r.rtSeconds = response.rtSeconds;
  r.onsetNs = response.onsetNs;
  r.responseNs = response.responseNs;
  r.note = response.note.empty() ? score.note : response.note;
  store_.recordResponse(r);
  s.usedSeconds[key] += response.rtSeconds.value_or(std::max(limit, 0.0));
  if (progress_) progress_({s.participant.participant, plan.sequence, int(s.plan.trials.size()), &plan, response.text, score.correct, response.rtSeconds});
  faultPoint("ack", ++acks_);
  return true;
}

void TrialRunner::stopAfterStorageError(Session& s, const SessionResult& result, std::size_t index, const StoreError& e) {
  try {
    store_.endSession(s.session, "storage error");
  } catch (const StoreError&) {
    // The same fault usually stops this write too; --resume does not need it.
  }
  const int safe = result.answeredBefore + result.answeredNow;
  throw StoreError("participant '" + s.participant.participant + "': session stopped, trial " + std::to_string(s.plan.trials[index].sequence) + "/" +
                       std::to_string(s.plan.trials.size()) + " was not stored (the " + std::to_string(safe) +
                       " responses acknowledged before it are safe): " + e.what(),
                   e.code());
}

void checkParticipant(Store& store, const Experiment& experiment, const RunOptions& options) {
  const auto existing = store.findParticipant(experiment.id, options.participant);
  if (existing && existing->status == "finished")
    throw StoreError("participant '" + options.participant + "' has already finished experiment '" + experiment.id +
                     "'; a second run is refused (use a new participant id)");
  if (existing && existing->status == "dropped")
    throw StoreError("participant '" + options.participant + "' dropped out of experiment '" + experiment.id +
                     "'; their slot was freed (use a new participant id)");
  if (existing && !options.resume)
    throw StoreError("participant '" + options.participant + "' has an unfinished session; continue it with --resume");
  if (!existing && options.resume)
    throw StoreError("participant '" + options.participant + "' has no session to resume in " + store.location());
}

std::vector<TrialRecord> TrialRunner::preparePlan(const SessionPlan& plan) {
  std::vector<TrialRecord> records;
  for (const auto& p : plan.trials) records.push_back(makeTrialRecord(p, stimuli_.prepare(p)));
  return records;
}

// A newcomer: every stimulus of the slot's plan is prepared before anything is written, then the
// version, the participant, the slot and the plan are stored in one transaction. Another station
// may take the predicted slot meanwhile: then the next free slot's plan is prepared instead.
ParticipantRecord TrialRunner::enrolNewcomer(const RunOptions& options, SessionPlan& plan) {
  for (int attempt = 0;; ++attempt) {
    const int slot = store_.nextFreeSlot(experiment_.id);
    plan = makeSessionPlan(experiment_, design_, slot);
    const auto records = preparePlan(plan);
    if (auto p = store_.enrol(experiment_, options.tlabVersion, options.participant, slot, design_, records)) return *p;
    if (attempt == 1000) throw StoreError(store_.location() + ": could not claim a free slot (other stations keep taking them)");
  }
}

SessionResult TrialRunner::run(const RunOptions& options, Responder& responder) {
  checkParticipant(store_, experiment_, options);
  faultPoint("open");
  const auto existing = store_.findParticipant(experiment_.id, options.participant);
  Session s{responder, {}, 0, {}, {}, {}, {}};
  if (existing) {
    s.participant = *existing;
    s.plan = makeSessionPlan(experiment_, design_, s.participant.slot);
  } else {
    s.participant = enrolNewcomer(options, s.plan);
  }
  s.stored = store_.trials(s.participant.id);
  if (s.stored.empty()) {  // a database from a tlab that stored the plan after enrolment
    store_.insertTrials(s.participant.id, preparePlan(s.plan));
    s.stored = store_.trials(s.participant.id);
  }
  if (s.stored.size() != s.plan.trials.size())
    throw StoreError("participant '" + options.participant + "': the stored plan has " + std::to_string(s.stored.size()) +
                     " trials but the experiment file gives " + std::to_string(s.plan.trials.size()) +
                     " (the design changed since this participant began): use a new participant id");

  SessionResult result;
  result.slot = s.participant.slot;
  result.total = int(s.plan.trials.size());
  std::size_t first = 0;
  while (first < s.stored.size() && s.stored[first].answered) ++first;
  for (const auto& t : s.stored) result.answeredBefore += t.answered ? 1 : 0;
  s.usedSeconds = store_.usedSeconds(s.participant.id);  // trial time limits continue where they were

  s.session = store_.startSession(s.participant.id, experiment_, options.tlabVersion, responder.mode());
  faultPoint("session", ++sessions_);
  auto close = [&](SessionOutcome outcome) {
    storeEvents(s, std::nullopt);
    store_.endSession(s.session, outcome == SessionOutcome::Finished ? "finished" : "closed");
    result.outcome = outcome;
    return result;
  };
  const std::string welcome = first == 0 ? experiment_.welcome : "Welcome back. The session continues where it stopped.";
  if (!welcome.empty() && !responder.showMessage(experiment_.title, welcome)) return close(SessionOutcome::Closed);
  if (!runQuestionnaires(s, "start", 0)) return close(SessionOutcome::Closed);
  // Blocks answered completely before an interruption still get their after-block questionnaires.
  for (std::size_t i = 0; i < first; ++i)
    if ((i + 1 == s.plan.trials.size() || s.plan.trials[i + 1].block != s.plan.trials[i].block) &&
        !runQuestionnaires(s, "after-block", s.plan.trials[i].block))
      return close(SessionOutcome::Closed);
  for (std::size_t i = first; i < s.plan.trials.size(); ++i) {
    if (s.stored[i].answered) continue;
    try {
      if (!runTrial(s, i)) return close(SessionOutcome::Closed);
    } catch (const StoreError& e) {
      stopAfterStorageError(s, result, i, e);
    }
    ++result.answeredNow;
    const bool blockEnds = i + 1 == s.plan.trials.size() || s.plan.trials[i + 1].block != s.plan.trials[i].block;
    if (blockEnds && !runQuestionnaires(s, "after-block", s.plan.trials[i].block)) return close(SessionOutcome::Closed);
  }
  if (!runQuestionnaires(s, "end", 0)) return close(SessionOutcome::Closed);
  store_.finishParticipant(s.participant.id);
  responder.showMessage(experiment_.title, experiment_.goodbye);
  return close(SessionOutcome::Finished);
}

}  // namespace tlab::study
