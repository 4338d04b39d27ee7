#include "study/replay/logged_trial.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "study/design/counterbalancing.hpp"
#include "study/design/experiment_file.hpp"
#include "study/store/study_table.hpp"

namespace tlab::study {

namespace {

// The cells of an export table's rows by column name.
class TableColumns {
 public:
  explicit TableColumns(const DataTable& table) : table_(table) {}
  const std::string& at(const std::vector<std::string>& row, const std::string& name) const {
    const auto it = std::find(table_.header.begin(), table_.header.end(), name);
    if (it == table_.header.end()) throw StoreError("export table without column '" + name + "'");
    return row[std::size_t(it - table_.header.begin())];
  }

 private:
  const DataTable& table_;
};

// The experiment text the participant enrolled under, parsed again where it was run.
Experiment enrolledExperiment(Store& store, const std::string& experimentId, const ParticipantRecord& participant) {
  for (const auto& v : store.versions(experimentId))
    if (v.row == participant.experiment) return parseExperiment(v.fileText, v.filePath, StimulusChecks::Skip);
  throw StoreError(store.location() + ": the experiment version of participant '" + participant.participant + "' is missing");
}

// The trial planned for the participant's slot, checked against the stored trial record.
PlannedTrial plannedTrial(const Experiment& e, const ParticipantRecord& participant, const TrialRecord& record, const std::string& name) {
  const SessionPlan plan = makeSessionPlan(e, makeDesign(e), participant.slot);
  for (const auto& t : plan.trials)
    if (t.sequence == record.sequence) {
      if (t.stimulus.text() != record.stimulusKey)
        throw StoreError(name + ": the plan rebuilt from the stored experiment shows '" + t.stimulus.text() + "', the stored trial '" +
                         record.stimulusKey + "'");
      return t;
    }
  throw StoreError(name + ": not in the plan rebuilt from the stored experiment");
}

void readResponse(Store& store, const Experiment& e, LoggedTrial& trial) {
  const DataTable trials = store.exportTable(ExportTable::Trials, e);
  const TableColumns c(trials);
  for (const auto& row : trials.rows) {
    if (c.at(row, "participant") != trial.participant || c.at(row, "sequence") != std::to_string(trial.plan.sequence)) continue;
    if (c.at(row, "responded") != "1") return;
    if (c.at(row, "answered") == "1") trial.answer = c.at(row, "raw_answer");
    trial.correct = c.at(row, "correct") == "1";
    if (!c.at(row, "rt_seconds").empty()) trial.rtSeconds = std::stod(c.at(row, "rt_seconds"));
    trial.responseNs = std::stoll(c.at(row, "response_ns"));
    return;
  }
}

void readSessions(Store& store, const Experiment& e, LoggedTrial& trial) {
  const DataTable sessions = store.exportTable(ExportTable::Sessions, e);
  const TableColumns c(sessions);
  for (const auto& row : sessions.rows) {
    const std::int64_t id = std::stoll(c.at(row, "session"));
    if (!std::any_of(trial.frames.begin(), trial.frames.end(), [&](const LoggedFrame& f) { return f.session == id; })) continue;
    FrameSession s;
    s.mode = c.at(row, "mode");
    const auto display = nlohmann::json::parse(c.at(row, "display"), nullptr, false);
    if (display.is_object()) {
      s.glRenderer = display.value("gl_renderer", "");
      s.tlabVersion = display.value("tlab_version", "");
    }
    trial.sessions[id] = s;
  }
}

}  // namespace

std::string trialName(const LoggedTrial& trial) {
  return "trial " + std::to_string(trial.plan.sequence) + " of participant '" + trial.participant + "'";
}

LoggedTrial loadLoggedTrial(Store& store, const std::string& experimentId, const std::string& participant, int sequence) {
  LoggedTrial trial;
  trial.location = store.location();
  trial.experimentId = storedExperiment(store, experimentId, true).experiment.id;
  trial.participant = participant;
  const auto who = store.findParticipant(trial.experimentId, participant);
  if (!who) throw StoreError(trial.location + ": no participant '" + participant + "' in experiment '" + trial.experimentId + "'");
  const std::vector<TrialRecord> records = store.trials(who->id);
  const auto record = std::find_if(records.begin(), records.end(), [&](const TrialRecord& r) { return r.sequence == sequence; });
  const std::string name = "trial " + std::to_string(sequence) + " of participant '" + participant + "'";
  if (record == records.end())
    throw StoreError(trial.location + ": participant '" + participant + "' has no trial " + std::to_string(sequence) + " (trials 1 to " +
                     std::to_string(records.size()) + ")");
  const Experiment e = enrolledExperiment(store, trial.experimentId, *who);
  trial.plan = plannedTrial(e, *who, *record, name);
  if (trial.plan.navigation == Navigation::None)
    throw StoreError(name + " (task " + trial.plan.taskId + ") is not interactive: its task has no navigation (orbit or walk) to replay");
  const auto question = nlohmann::json::parse(record->questionJson, nullptr, false);
  trial.question = question.is_object() ? question.value("text", "") : "";
  trial.truth = record->truthJson;
  for (const auto& row : store.trialFrames(record->id).rows) {
    try {
      trial.frames.push_back({parseFrameJson(row[2]), std::stoll(row[0])});
    } catch (const std::invalid_argument& error) {
      throw StoreError(name + ": stored frame " + std::to_string(trial.frames.size()) + ": " + error.what());
    }
  }
  if (trial.frames.empty())
    throw StoreError(name + " (task " + trial.plan.taskId + ") has no live frames logged: it was not shown yet, or shown by a tlab that did "
                     "not log frames");
  readResponse(store, e, trial);
  readSessions(store, e, trial);
  return trial;
}

}  // namespace tlab::study
