// TrialRunner's enrolment: who is running (checkParticipant), a newcomer's plan prepared and
// stored before anything is shown, the welcome and consent before a newcomer is enrolled, and
// the stored plan of a returning participant. The session itself runs in trial_runner.cpp.
#include <nlohmann/json.hpp>

#include "study/run/trial_runner.hpp"
#include "study/design/session_plan.hpp"
#include "study/run/plan_checks.hpp"
#include "tasks/question_json.hpp"

namespace tlab::study {

namespace {

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

void checkParticipant(Store& store, const Experiment& experiment, const RunOptions& options) {
  const auto existing = store.findParticipant(experiment.id, options.participant);
  if (existing && existing->status == "finished")
    throw StoreError("participant '" + options.participant + "' has already finished experiment '" + experiment.id +
                     "'; a second run is refused (use a new participant id)");
  if (existing && existing->status == "declined")
    throw StoreError("participant '" + options.participant + "' declined to take part in experiment '" + experiment.id +
                     "'; only that was stored (use a new participant id if they change their mind)");
  if (existing && existing->status == "dropped")
    throw StoreError("participant '" + options.participant + "' dropped out of experiment '" + experiment.id +
                     "'; their slot was freed (use a new participant id)");
  if (existing && !options.resume)
    throw StoreError("participant '" + options.participant + "' has an unfinished session; continue it with --resume");
  if (!existing && options.resume)
    throw StoreError("participant '" + options.participant + "' has no session to resume in " + store.location());
}

// Every stimulus of the plan, and the check that no training stimulus is shown again in a test
// trial (a participant would learn its answer; `tlab design` checks the same before any start).
std::vector<TrialRecord> TrialRunner::preparePlan(const SessionPlan& plan) {
  std::vector<TrialRecord> records;
  for (const auto& p : plan.trials) records.push_back(makeTrialRecord(p, stimuli_.prepare(p)));
  if (const auto clash = trainingShownInTest(records)) throw StoreError(clash->message());
  return records;
}

// A newcomer: every stimulus of the predicted slot's plan is prepared before anything is written,
// then the version, the participant, the slot and the plan are stored in one transaction.
// Another station may take the predicted slot meanwhile: then the next free slot's plan is
// prepared instead.
TrialRunner::Newcomer TrialRunner::prepareNewcomer() {
  Newcomer n;
  n.slot = store_.nextFreeSlot(experiment_.id);
  n.plan = makeSessionPlan(experiment_, design_, n.slot);
  n.records = preparePlan(n.plan);
  return n;
}

ParticipantRecord TrialRunner::enrolNewcomer(const RunOptions& options, Newcomer& n) {
  for (int attempt = 0;; ++attempt) {
    if (auto p = store_.enrol(experiment_, options.tlabVersion, options.participant, n.slot, design_, n.records)) return *p;
    if (attempt == 1000) throw StoreError(store_.location() + ": could not claim a free slot (other stations keep taking them)");
    n = prepareNewcomer();
  }
}

std::string TrialRunner::participantTitle() const {
  return experiment_.participantTitle.empty() ? experiment_.texts.text("title.welcome") : experiment_.participantTitle;
}

// Welcome and consent come before anything is stored of a newcomer; a decline stores only that.
std::optional<SessionOutcome> TrialRunner::greetNewcomer(const RunOptions& options, Responder& responder) {
  if (!experiment_.welcome.empty() && !responder.showMessage(participantTitle(), experiment_.welcome)) return SessionOutcome::Closed;
  if (!experiment_.consent) return std::nullopt;
  const auto accepted = responder.askConsent(participantTitle(), *experiment_.consent);
  if (!accepted) return SessionOutcome::Closed;
  if (*accepted) return std::nullopt;
  store_.recordDecline(experiment_, options.tlabVersion, options.participant);
  responder.showMessage(participantTitle(), experiment_.texts.text("flow.declined"));
  return SessionOutcome::Declined;
}

// Who runs, and their plan: a returning participant's slot plan, or a newcomer greeted and
// enrolled. Stimuli first (nothing written); without a consent form the newcomer is enrolled at
// once, with one only after agreeing (a decline stores just the decision). An outcome: declined,
// or closed at the welcome or consent.
std::optional<SessionOutcome> TrialRunner::admit(const RunOptions& options, Responder& responder,
                                                 const std::optional<ParticipantRecord>& existing,
                                                 ParticipantRecord& participant, SessionPlan& plan) {
  if (existing) {
    participant = *existing;
    plan = makeSessionPlan(experiment_, design_, participant.slot);
    return std::nullopt;
  }
  Newcomer n = prepareNewcomer();
  if (!experiment_.consent) participant = enrolNewcomer(options, n);
  if (const auto outcome = greetNewcomer(options, responder)) return outcome;
  if (experiment_.consent) participant = enrolNewcomer(options, n);
  plan = n.plan;
  return std::nullopt;
}

// The participant's stored trials, which must match the plan the experiment file gives now.
std::vector<TrialRecord> TrialRunner::storedPlan(const RunOptions& options, const ParticipantRecord& participant,
                                                 const SessionPlan& plan) {
  std::vector<TrialRecord> stored = store_.trials(participant.id);
  if (stored.empty()) {  // a database from a tlab that stored the plan after enrolment
    store_.insertTrials(participant.id, preparePlan(plan));
    stored = store_.trials(participant.id);
  }
  if (stored.size() != plan.trials.size())
    throw StoreError("participant '" + options.participant + "': the stored plan has " + std::to_string(stored.size()) +
                     " trials but the experiment file gives " + std::to_string(plan.trials.size()) +
                     " (the design changed since this participant began): use a new participant id");
  return stored;
}

}  // namespace tlab::study
