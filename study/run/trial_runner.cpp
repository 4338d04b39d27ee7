// TrialRunner's session: opening it (consent, participant information), each trial shown,
// answered, scored and stored, questionnaires, breaks and the end. Enrolment and the stored plan:
// trial_runner_enrol.cpp.
#include "study/run/trial_runner.hpp"

#include <map>
#include <set>
#include <variant>

#include <nlohmann/json.hpp>

#include "study/store/fault_point.hpp"
#include "study/run/session_wording.hpp"
#include "study/design/form_field.hpp"
#include "study/design/session_plan.hpp"
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

// The front end checked the answers; the runner checks them again before storing (a browser is not trusted).
std::vector<FormAnswer> formAnswers(const std::vector<FormField>& fields, const std::vector<std::string>& values) {
  if (values.size() != fields.size()) throw StoreError("a form came back with " + std::to_string(values.size()) + " answers for " +
                                                       std::to_string(fields.size()) + " fields");
  std::vector<FormAnswer> out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::string error = fieldError(fields[i], values[i]);
    if (!error.empty()) throw StoreError("form field '" + fields[i].id + "': " + error);
    out.push_back({fields[i].id, values[i], fieldNumber(fields[i], values[i])});
  }
  return out;
}

// The right answer in words, for training feedback.
std::string rightAnswerText(const tasks::Question& q) {
  return std::visit(
      [](const auto& truth) -> std::string {
        using T = std::decay_t<decltype(truth)>;
        if constexpr (std::is_same_v<T, std::int64_t>) return std::to_string(truth);
        else if constexpr (std::is_same_v<T, std::string>) return truth;
        else if constexpr (std::is_same_v<T, std::set<std::string>>) {
          std::string text;
          for (const auto& label : truth) text += (text.empty() ? "" : ", ") + label;
          return text.empty() ? "none" : text;
        } else {
          char buf[64];
          std::snprintf(buf, sizeof buf, "%.1f, %.1f", truth.x, truth.y);
          return buf;
        }
      },
      q.truth);
}

// 1-based position of trial `index` among the plan's trials of its phase, and how many there are.
std::pair<int, int> phasePosition(const SessionPlan& plan, std::size_t index) {
  int position = 0, total = 0;
  for (std::size_t i = 0; i < plan.trials.size(); ++i) {
    if (plan.trials[i].phase != plan.trials[index].phase) continue;
    ++total;
    if (i <= index) ++position;
  }
  return {position, total};
}

bool endsBlock(const SessionPlan& plan, std::size_t i) { return i + 1 == plan.trials.size() || plan.trials[i + 1].block != plan.trials[i].block; }

}  // namespace

TrialRunner::TrialRunner(const Experiment& experiment, Store& store, StimulusSource& stimuli)
    : experiment_(experiment), store_(store), stimuli_(stimuli), design_(makeDesign(experiment)) {}

void TrialRunner::storeEvents(Session& s, std::optional<std::int64_t> trial) {
  store_.recordEvents(s.session, trial, s.responder.takeEvents());  // one transaction: a live trial's frames are many
}

bool TrialRunner::runQuestionnaires(Session& s, const std::string& when, int block) {
  for (const auto& q : experiment_.questionnaires) {
    if (q.when != when || store_.hasQuestionnaireAnswers(s.participant.id, q.id, block)) continue;
    const auto values = s.responder.fillForm(q.title.empty() ? experiment_.texts.text("title.questionnaire") : q.title, q.items);
    storeEvents(s, std::nullopt);
    if (!values) return false;
    store_.recordQuestionnaire(s.participant.id, s.session, q.id, block, formAnswers(q.items, *values));
  }
  return true;
}

ResponseRecord TrialRunner::scoreResponse(const Session& s, const TrialRecord& record, const PreparedTrial& prepared,
                                          const Response& response, double limit, tasks::Score& score) const {
  tasks::Answer answer{response.text, response.rtSeconds};
  if (answer.text && answer.seconds && *answer.seconds > limit) answer.text.reset();  // over the limit: missing
  try {
    score = tasks::makeTask(record.task)->score(prepared.question, answer);
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
  r.onsetFrameMs = response.onsetFrameMs;
  r.lateFrames = response.lateFrames;
  r.onsetToSwapMs = response.onsetToSwapMs;
  return r;
}

bool TrialRunner::runTrial(Session& s, std::size_t index) {
  const PlannedTrial& plan = s.plan.trials[index];
  const TrialRecord& record = s.stored[index];
  const PreparedTrial prepared = stimuli_.prepare(plan);
  if (prepared.stimulusSha256 != record.stimulusSha256)
    throw StoreError("trial " + std::to_string(plan.sequence) + ": the stimulus differs from the one stored when the session began "
                     "(sha256 " + prepared.stimulusSha256.substr(0, 12) + " vs " + record.stimulusSha256.substr(0, 12) + ")");
  if (plan.taskId != s.lastTask) {
    const TaskSpec* spec = experiment_.task(plan.taskId);
    // Never the task's internal id: "Practice" or "Instructions" in the participants' language.
    const std::string& title = experiment_.texts.text(plan.phase == Phase::Training ? "title.practice" : "title.instructions");
    const std::string instructions = spec->instructions.empty() ? questionWording(prepared.question, experiment_.texts) : spec->instructions;
    if (!s.responder.showMessage(title, taskIntroduction(s.plan, index, instructions, experiment_.texts)))
      return false;
    s.lastTask = plan.taskId;
  }
  double limit = plan.timeLimitSeconds;
  const std::string key = trialKey(plan);
  if (plan.trialTimeLimitSeconds) limit = std::min(limit, *plan.trialTimeLimitSeconds - s.usedSeconds[key]);

  const auto [position, total] = phasePosition(s.plan, index);
  TrialView view{plan, prepared, limit, position, total, {}};
  Response response;
  if (limit <= 0.0) {
    response.note = "trial time limit reached";  // never shown: missing, which counts as wrong
  } else {
    view.onset = [&](std::int64_t tNs, const std::string& detail) {
      store_.recordOnset(s.session, record.id, tNs, detail);
      faultPoint("onset", ++onsets_);
    };
    const auto given = s.responder.respond(view);
    storeEvents(s, record.id);
    if (!given) return false;
    response = *given;
  }
  tasks::Score score;
  store_.recordResponse(scoreResponse(s, record, prepared, response, limit, score));
  s.usedSeconds[key] += response.rtSeconds.value_or(std::max(limit, 0.0));
  if (progress_) progress_({s.participant.participant, plan.sequence, int(s.plan.trials.size()), &plan, response.text, score.correct, response.rtSeconds});
  faultPoint("ack", ++acks_);
  if (plan.phase == Phase::Training && experiment_.trainingFeedback && limit > 0.0) {
    const bool shown = s.responder.showFeedback(view, {score.correct, rightAnswerText(prepared.question), response.text});
    storeEvents(s, record.id);
    return shown;
  }
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

// After the session has started: consent (when not yet recorded) and participant information.
std::optional<SessionOutcome> TrialRunner::openSession(Session& s, bool newcomer) {
  storeEvents(s, std::nullopt);  // what came before the session (a newcomer's consent and size calibration): stored now
  if (experiment_.consent && !store_.hasConsent(s.participant.id)) {
    const auto accepted = newcomer ? std::optional<bool>(true) : s.responder.askConsent(participantTitle(), *experiment_.consent);
    if (!accepted) return SessionOutcome::Closed;
    store_.recordConsent(s.participant.id, s.session, *accepted);
    storeEvents(s, std::nullopt);
    if (!*accepted) {
      store_.dropParticipant(experiment_.id, s.participant.participant, "declined consent");
      return SessionOutcome::Declined;
    }
  }
  if (!newcomer && !s.responder.showMessage(participantTitle(), experiment_.texts.text("flow.welcome_back")))
    return SessionOutcome::Closed;
  if (!experiment_.info.empty() && !store_.hasInfo(s.participant.id)) {
    const auto values = s.responder.fillForm(experiment_.texts.text("title.about_you"), experiment_.info);
    storeEvents(s, std::nullopt);
    if (!values) return SessionOutcome::Closed;
    store_.recordInfo(s.participant.id, s.session, formAnswers(experiment_.info, *values));
  }
  if (!runQuestionnaires(s, "start", 0)) return SessionOutcome::Closed;
  return std::nullopt;
}

// Between trials: "training is over" before the first test trial after training, and breaks
// every N test trials or blocks. False: the session was closed.
bool TrialRunner::betweenTrials(Session& s, std::size_t done) {
  const auto& trials = s.plan.trials;
  if (done + 1 >= trials.size()) return true;
  const PlannedTrial& last = trials[done];
  if (last.phase == Phase::Training && trials[done + 1].phase == Phase::Test) {
    const bool shown =
        s.responder.showMessage(participantTitle(), experiment_.texts.text(experiment_.trainingFeedback ? "flow.training_over_no_feedback" : "flow.training_over"));
    storeEvents(s, std::nullopt);
    return shown;
  }
  const BreakSpec& b = experiment_.breaks;
  if (b.every <= 0 || last.phase != Phase::Test) return true;
  int count = 0;
  for (std::size_t i = 0; i <= done; ++i)
    if (trials[i].phase == Phase::Test && (!b.blocks || endsBlock(s.plan, i))) ++count;
  if ((b.blocks && !endsBlock(s.plan, done)) || count % b.every != 0) return true;
  BreakSpec shown = b;  // the break says what is left
  shown.text = breakText(s.plan, done, b, experiment_.texts);
  const bool continued = s.responder.takeBreak(shown);
  storeEvents(s, std::nullopt);
  return continued;
}

// The trials from the first unanswered one on, each block's questionnaires and breaks, then the
// end questionnaires and the debrief. Closed: the participant closed the session on the way.
SessionOutcome TrialRunner::runTrials(Session& s, std::size_t first, SessionResult& result) {
  // Blocks answered completely before an interruption still get their after-block questionnaires.
  for (std::size_t i = 0; i < first; ++i)
    if (endsBlock(s.plan, i) && !runQuestionnaires(s, "after-block", s.plan.trials[i].block)) return SessionOutcome::Closed;
  for (std::size_t i = first; i < s.plan.trials.size(); ++i) {
    if (s.stored[i].answered) continue;
    try {
      if (!runTrial(s, i)) return SessionOutcome::Closed;
    } catch (const StoreError& e) {
      stopAfterStorageError(s, result, i, e);
    }
    ++result.answeredNow;
    if (endsBlock(s.plan, i) && !runQuestionnaires(s, "after-block", s.plan.trials[i].block)) return SessionOutcome::Closed;
    if (!betweenTrials(s, i)) return SessionOutcome::Closed;
  }
  if (!runQuestionnaires(s, "end", 0)) return SessionOutcome::Closed;
  store_.finishParticipant(s.participant.id);
  s.responder.showDebrief(participantTitle(), experiment_.debrief);
  return SessionOutcome::Finished;
}

SessionResult TrialRunner::run(const RunOptions& options, Responder& responder) {
  checkParticipant(store_, experiment_, options);
  faultPoint("open");
  const auto existing = store_.findParticipant(experiment_.id, options.participant);
  SessionResult result;
  responder.useTexts(experiment_.texts);
  Session s{responder, {}, 0, {}, {}, {}, {}};
  if (const auto outcome = admit(options, responder, existing, s.participant, s.plan)) {
    result.outcome = *outcome;
    return result;
  }
  s.stored = storedPlan(options, s.participant, s.plan);
  result.slot = s.participant.slot;
  result.total = int(s.plan.trials.size());
  std::size_t first = 0;
  while (first < s.stored.size() && s.stored[first].answered) ++first;
  for (const auto& t : s.stored) result.answeredBefore += t.answered ? 1 : 0;
  s.usedSeconds = store_.usedSeconds(s.participant.id);  // trial time limits continue where they were

  s.session = store_.startSession(s.participant.id, experiment_, options.tlabVersion, responder.mode());
  faultPoint("session", ++sessions_);
  if (const auto display = responder.display()) {
    // With the version of tlab that ran it: `tlab replay` names it when a logged frame differs.
    nlohmann::json shown = nlohmann::json::parse(display->json());
    shown["tlab_version"] = options.tlabVersion;
    store_.recordDisplay(s.session, shown.dump());
  }
  auto close = [&](SessionOutcome outcome) {
    storeEvents(s, std::nullopt);
    const char* reason = outcome == SessionOutcome::Finished ? "finished" : outcome == SessionOutcome::Declined ? "declined" : "closed";
    store_.endSession(s.session, reason);
    result.outcome = outcome;
    return result;
  };
  if (const auto outcome = openSession(s, !existing)) return close(*outcome);
  return close(runTrials(s, first, result));
}

}  // namespace tlab::study
