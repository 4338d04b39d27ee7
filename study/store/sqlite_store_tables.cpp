// SqliteStore: the tables that export and analysis read — trials (one column per factor, the
// response, the session's version and status, how often the stimulus was shown), sessions,
// questionnaire answers, participants, events, and the records of one dependent variable.
#include <map>

#include <nlohmann/json.hpp>

#include "study/store/sqlite_store.hpp"

namespace tlab::study {

namespace {

// Every participant of every version of the experiment (?1 is the experiment id).
constexpr const char* kOfExperiment = "IN (SELECT id FROM experiments WHERE experiment_id = ?1)";

std::string cell(const Statement& s, int column) { return s.isNull(column) ? "" : s.text(column); }

std::string numberCell(const Statement& s, int column) {
  if (s.isNull(column)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", s.real(column));
  return buf;
}

const std::map<std::string, std::string> kDependentVariableSql = {
    {"correct", "r.correct"}, {"score", "r.score"},           {"rt", "r.rt_seconds"},
    {"error", "r.error"},     {"partial_credit", "r.partial_credit"}, {"answered", "r.answered"}};

}  // namespace

// Session id → "finished", "closed", "storage error", "interrupted", "interrupted, resumed by
// session N" or "running" (its station's process is alive on this machine).
std::map<std::string, std::string> SqliteStore::sessionStatuses() {
  Statement s = db_->prepare(
      "SELECT id, ended_at IS NOT NULL, coalesce(end_reason, ''), resumed_by, coalesce(station, ''), coalesce(process_start, '') "
      "FROM sessions");
  std::map<std::string, std::string> out;
  while (s.step()) {
    std::string status = s.text(2);
    if (!s.isNull(3)) status = "interrupted, resumed by session " + s.text(3);
    else if (!s.integer(1)) status = stationState(s.text(4), s.text(5)) == "alive" ? "running" : "interrupted";
    out[s.text(0)] = status;
  }
  return out;
}

DataTable SqliteStore::trialsTable(const Experiment& e) {
  DataTable t;
  t.header = {"experiment", "participant", "slot", "participant_status", "sequence", "phase", "block", "condition"};
  for (const auto& f : e.factors) t.header.push_back(f.name);
  t.header.insert(t.header.end(), {"task_id", "task", "trial", "question", "answer_kind", "truth", "responded", "raw_answer", "answered",
                                   "correct", "score", "partial_credit", "error", "rt_seconds", "time_limit", "onset_ns",
                                   "response_ns", "note", "stimulus_path", "stimulus_sha256", "probe_seed", "session", "recorded_at",
                                   "experiment_version", "session_status", "showings", "onset_frame_ms", "late_frames",
                                   "onset_to_swap_ms"});
  const auto statuses = sessionStatuses();
  Statement s = db_->prepare(
      std::string("SELECT p.participant, p.slot, p.status, t.sequence, t.phase, t.block, t.condition, t.levels_json, t.task_id, t.task, "
      "t.trial, t.question, t.answer_kind, t.truth_json, r.id IS NOT NULL, r.raw_answer, r.answered, r.correct, r.score, "
      "r.partial_credit, r.error, r.rt_seconds, t.time_limit, r.onset_ns, r.response_ns, r.note, t.stimulus_path, "
      "t.stimulus_sha256, t.probe_seed, r.session, r.recorded_at, x.version, "
      "(SELECT count(*) FROM events e WHERE e.trial = t.id AND e.kind = 'onset'), r.onset_frame_ms, r.late_frames, r.onset_to_swap_ms "
      "FROM trials t JOIN participants p ON p.id = t.participant "
      "LEFT JOIN responses r ON r.trial = t.id LEFT JOIN sessions ss ON ss.id = r.session "
      "LEFT JOIN experiments x ON x.id = ss.experiment WHERE p.experiment ") + kOfExperiment +
      " ORDER BY p.slot, p.id, t.sequence");
  s.bind(1, e.id);
  while (s.step()) {
    std::vector<std::string> row = {e.id, cell(s, 0), cell(s, 1), cell(s, 2), cell(s, 3), cell(s, 4), cell(s, 5), cell(s, 6)};
    const auto levels = nlohmann::json::parse(s.text(7));
    for (const auto& f : e.factors) row.push_back(levels.value(f.name, std::string()));
    for (int c = 8; c <= 13; ++c) row.push_back(cell(s, c));
    row.push_back(s.integer(14) ? "1" : "0");
    for (int c = 15; c <= 17; ++c) row.push_back(cell(s, c));
    for (int c = 18; c <= 22; ++c) row.push_back(numberCell(s, c));
    for (int c = 23; c <= 27; ++c) row.push_back(cell(s, c));
    // A 64-bit seed above 2^53 is not a double: "seed:" keeps R (read.csv) and pandas from reading it as a number.
    row.push_back("seed:" + std::to_string(std::uint64_t(s.integer(28))));
    for (int c = 29; c <= 31; ++c) row.push_back(cell(s, c));
    const auto status = statuses.find(cell(s, 29));
    row.push_back(status == statuses.end() ? "" : status->second);
    row.push_back(cell(s, 32));
    row.push_back(numberCell(s, 33));
    row.push_back(cell(s, 34));
    row.push_back(numberCell(s, 35));
    t.rows.push_back(std::move(row));
  }
  return t;
}

DataTable SqliteStore::sessionsTable(const Experiment& e) {
  DataTable t;
  t.header = {"experiment", "participant", "session", "experiment_version", "mode", "station", "started_at", "ended_at",
              "status", "resumed_by", "responses", "onsets", "display"};
  const auto statuses = sessionStatuses();
  Statement s = db_->prepare(
      std::string("SELECT p.participant, s.id, x.version, s.mode, s.station, s.started_at, s.ended_at, s.resumed_by, "
      "(SELECT count(*) FROM responses r WHERE r.session = s.id), "
      "(SELECT count(*) FROM events e WHERE e.session = s.id AND e.kind = 'onset'), s.display_json "
      "FROM sessions s JOIN participants p ON p.id = s.participant LEFT JOIN experiments x ON x.id = s.experiment "
      "WHERE p.experiment ") + kOfExperiment + " ORDER BY s.id");
  s.bind(1, e.id);
  while (s.step()) {
    const auto status = statuses.find(cell(s, 1));
    t.rows.push_back({e.id, cell(s, 0), cell(s, 1), cell(s, 2), cell(s, 3), cell(s, 4), cell(s, 5), cell(s, 6),
                      status == statuses.end() ? "" : status->second, cell(s, 7), cell(s, 8), cell(s, 9), cell(s, 10)});
  }
  return t;
}

DataTable SqliteStore::queryTable(const std::string& experimentId, std::vector<std::string> header, const std::string& sql) {
  DataTable t;
  t.header = std::move(header);
  Statement s = db_->prepare(sql);
  s.bind(1, experimentId);
  while (s.step()) {
    std::vector<std::string> row = {experimentId};
    for (int c = 0; c + 1 < int(t.header.size()); ++c) row.push_back(cell(s, c));
    t.rows.push_back(std::move(row));
  }
  return t;
}

DataTable SqliteStore::exportTable(ExportTable table, const Experiment& e) {
  const std::string of = kOfExperiment;
  switch (table) {
    case ExportTable::Trials: return trialsTable(e);
    case ExportTable::Sessions: return sessionsTable(e);
    case ExportTable::Questionnaires:
      return queryTable(e.id, {"experiment", "participant", "questionnaire", "block", "item", "answer", "value", "session", "recorded_at"},
                        "SELECT p.participant, q.questionnaire, q.block, q.item, q.answer, q.value, q.session, q.recorded_at "
                        "FROM questionnaire_answers q JOIN participants p ON p.id = q.participant WHERE p.experiment " + of +
                            " ORDER BY p.slot, q.id");
    case ExportTable::Participants:
      return queryTable(e.id, {"experiment", "participant", "slot", "design_row", "between_cell", "block_order", "status", "assigned_at",
                               "finished_at"},
                        "SELECT p.participant, a.slot, a.design_row, a.between_cell, a.block_order, a.status, a.assigned_at, "
                        "p.finished_at FROM assignments a JOIN participants p ON p.id = a.participant WHERE a.experiment " + of +
                            " ORDER BY a.slot, a.id");
    case ExportTable::Events:
      return queryTable(e.id, {"experiment", "participant", "session", "trial_sequence", "t_ns", "kind", "detail"},
                        "SELECT p.participant, e.session, t.sequence, e.t_ns, e.kind, e.detail FROM events e "
                        "JOIN sessions s ON s.id = e.session JOIN participants p ON p.id = s.participant "
                        "LEFT JOIN trials t ON t.id = e.trial WHERE p.experiment " + of + " ORDER BY e.id");
    case ExportTable::Info:
      return queryTable(e.id, {"experiment", "participant", "field", "value", "number", "session", "recorded_at"},
                        "SELECT p.participant, i.field, i.value, i.number, i.session, i.recorded_at FROM participant_info i "
                        "JOIN participants p ON p.id = i.participant WHERE p.experiment " + of + " ORDER BY p.id, i.id");
    case ExportTable::Consent:
      return queryTable(e.id, {"experiment", "participant", "decision", "session", "recorded_at"},
                        "SELECT p.participant, c.decision, c.session, c.recorded_at FROM consent c "
                        "JOIN participants p ON p.id = c.participant WHERE p.experiment " + of + " ORDER BY c.id");
  }
  throw StoreError("unknown export table");
}

std::vector<AnalysisRecord> SqliteStore::analysisRecords(const std::string& experimentId, const std::string& dv) {
  const auto column = kDependentVariableSql.find(dv);
  if (column == kDependentVariableSql.end()) throw StoreError("unknown dependent variable '" + dv + "'");
  Statement s = db_->prepare(
      "SELECT p.participant, t.levels_json, t.task_id, t.block, " + column->second + ", t.id FROM trials t "
      "JOIN participants p ON p.id = t.participant JOIN responses r ON r.trial = t.id "
      "WHERE p.experiment " + std::string(kOfExperiment) + " AND p.status != 'dropped' AND t.phase = 'test' AND " + column->second +
      " IS NOT NULL ORDER BY p.id, t.sequence");
  s.bind(1, experimentId);
  std::vector<AnalysisRecord> out;
  while (s.step()) out.push_back({s.text(0), s.text(1), s.text(2), int(s.integer(3)), s.real(4), std::size_t(s.integer(5))});
  return out;
}

std::vector<std::map<std::string, int>> SqliteStore::sessionModes(const std::string& experimentId) {
  Statement s = db_->prepare("SELECT s.participant, s.mode, count(*) FROM sessions s JOIN participants p ON p.id = s.participant "
                             "WHERE p.experiment " + std::string(kOfExperiment) + " GROUP BY s.participant, s.mode ORDER BY s.participant");
  s.bind(1, experimentId);
  std::vector<std::map<std::string, int>> out;
  std::int64_t last = -1;
  while (s.step()) {
    if (s.integer(0) != last) out.emplace_back(), last = s.integer(0);
    out.back()[s.text(1)] = int(s.integer(2));
  }
  return out;
}

std::vector<StoredAnswer> SqliteStore::formAnswers(const std::string& experimentId) {
  Statement s = db_->prepare(
      "SELECT p.participant, a.questionnaire, a.item, a.answer, a.value, a.id FROM questionnaire_answers a "
      "JOIN participants p ON p.id = a.participant WHERE p.experiment " + std::string(kOfExperiment) + " AND p.status != 'dropped' "
      "UNION ALL SELECT p.participant, 'info', i.field, i.value, i.number, i.id FROM participant_info i "
      "JOIN participants p ON p.id = i.participant WHERE p.experiment " + std::string(kOfExperiment) + " AND p.status != 'dropped' "
      "ORDER BY 2, 6");
  s.bind(1, experimentId);
  std::vector<StoredAnswer> out;
  while (s.step()) out.push_back({s.text(0), s.text(1), s.text(2), s.text(3), s.optionalReal(4), std::size_t(s.integer(5))});
  return out;
}

DataTable SqliteStore::stimulusSummary(const std::string& experimentId) {
  DataTable t;
  t.header = {"condition", "task", "phase", "stimulus", "file", "sha256", "trials", "participants"};
  Statement s = db_->prepare(
      "SELECT t.condition, t.task_id, t.phase, t.stimulus_key, t.stimulus_path, t.stimulus_sha256, COUNT(*), "
      "COUNT(DISTINCT t.participant) FROM trials t JOIN participants p ON p.id = t.participant "
      "WHERE p.experiment " + std::string(kOfExperiment) + " GROUP BY t.stimulus_sha256, t.stimulus_key, t.phase, t.condition, t.task_id "
      "ORDER BY t.phase DESC, t.condition, t.task_id, t.stimulus_key");
  s.bind(1, experimentId);
  while (s.step()) t.rows.push_back({s.text(0), s.text(1), s.text(2), s.text(3), s.text(4), s.text(5), cell(s, 6), cell(s, 7)});
  return t;
}

DataTable SqliteStore::stimulusExamples(const std::string& experimentId) {
  DataTable t;
  t.header = {"condition", "task", "file"};
  Statement s = db_->prepare(
      "SELECT t.condition, t.task_id, t.stimulus_path, MIN(t.id) FROM trials t JOIN participants p ON p.id = t.participant "
      "WHERE p.experiment " + std::string(kOfExperiment) + " AND t.phase = 'test' GROUP BY t.condition, t.task_id "
      "ORDER BY t.condition, t.task_id");
  s.bind(1, experimentId);
  while (s.step()) t.rows.push_back({s.text(0), s.text(1), s.text(2)});
  return t;
}

}  // namespace tlab::study
