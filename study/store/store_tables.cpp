// The tables export and analysis read — trials (one column per factor, the response, the session's
// version and status, how often the stimulus was shown), sessions, questionnaire answers,
// participants, events, and the records of one dependent variable — in SQL that SQLite and
// PostgreSQL both run (?1 is the experiment id; PostgreSQL's store writes it $1).
#include "study/store/store_tables.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>
#include <sqlite3.h>

namespace tlab::study {

namespace {

// Every participant of every version of the experiment (?1 is the experiment id).
constexpr const char* kOfExperiment = "IN (SELECT id FROM experiments WHERE experiment_id = ?1)";

std::string cell(const ResultRow& s, int column) { return s.isNull(column) ? "" : s.text(column); }

std::string numberCell(const ResultRow& s, int column) {
  if (s.isNull(column)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", s.real(column));
  return buf;
}

const std::map<std::string, std::string> kDependentVariableSql = {
    {"correct", "r.correct"}, {"score", "r.score"},           {"rt", "r.rt_seconds"},
    {"error", "r.error"},     {"partial_credit", "r.partial_credit"}, {"answered", "r.answered"}};

// Session id → "finished", "closed", "storage error", "interrupted", "interrupted, resumed by
// session N" or "running" (its station's process is alive on this machine).
std::map<std::string, std::string> sessionStatuses(TableQueries& q) {
  std::map<std::string, std::string> out;
  q.forEachRow("SELECT id, CASE WHEN ended_at IS NULL THEN 0 ELSE 1 END, coalesce(end_reason, ''), resumed_by, "
               "coalesce(station, ''), coalesce(process_start, '') FROM sessions",
               "", [&](const ResultRow& s) {
                 std::string status = s.text(2);
                 if (!s.isNull(3)) status = "interrupted, resumed by session " + s.text(3);
                 else if (!s.integer(1)) status = stationState(s.text(4), s.text(5)) == "alive" ? "running" : "interrupted";
                 out[s.text(0)] = status;
               });
  return out;
}

std::vector<std::string> trialsRow(const Experiment& e, const ResultRow& s, const std::map<std::string, std::string>& statuses) {
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
  return row;
}

DataTable trialsTable(TableQueries& q, const Experiment& e) {
  DataTable t;
  t.header = {"experiment", "participant", "slot", "participant_status", "sequence", "phase", "block", "condition"};
  for (const auto& f : e.factors) t.header.push_back(f.name);
  t.header.insert(t.header.end(), {"task_id", "task", "trial", "question", "answer_kind", "truth", "responded", "raw_answer", "answered",
                                   "correct", "score", "partial_credit", "error", "rt_seconds", "time_limit", "onset_ns",
                                   "response_ns", "note", "stimulus_path", "stimulus_sha256", "probe_seed", "session", "recorded_at",
                                   "experiment_version", "session_status", "showings", "onset_frame_ms", "late_frames",
                                   "onset_to_swap_ms"});
  const auto statuses = sessionStatuses(q);
  q.forEachRow(
      std::string("SELECT p.participant, p.slot, p.status, t.sequence, t.phase, t.block, t.condition, t.levels_json, t.task_id, t.task, "
      "t.trial, t.question, t.answer_kind, t.truth_json, CASE WHEN r.id IS NULL THEN 0 ELSE 1 END, r.raw_answer, r.answered, "
      "r.correct, r.score, r.partial_credit, r.error, r.rt_seconds, t.time_limit, r.onset_ns, r.response_ns, r.note, t.stimulus_path, "
      "t.stimulus_sha256, t.probe_seed, r.session, r.recorded_at, x.version, "
      "(SELECT count(*) FROM events e WHERE e.trial = t.id AND e.kind = 'onset'), r.onset_frame_ms, r.late_frames, r.onset_to_swap_ms "
      "FROM trials t JOIN participants p ON p.id = t.participant "
      "LEFT JOIN responses r ON r.trial = t.id LEFT JOIN sessions ss ON ss.id = r.session "
      "LEFT JOIN experiments x ON x.id = ss.experiment WHERE p.experiment ") + kOfExperiment +
      " ORDER BY p.slot, p.id, t.sequence",
      e.id, [&](const ResultRow& s) { t.rows.push_back(trialsRow(e, s, statuses)); });
  return t;
}

DataTable sessionsTable(TableQueries& q, const Experiment& e) {
  DataTable t;
  t.header = {"experiment", "participant", "session", "experiment_version", "mode", "station", "started_at", "ended_at",
              "status", "resumed_by", "responses", "onsets", "display"};
  const auto statuses = sessionStatuses(q);
  q.forEachRow(
      std::string("SELECT p.participant, s.id, x.version, s.mode, s.station, s.started_at, s.ended_at, s.resumed_by, "
      "(SELECT count(*) FROM responses r WHERE r.session = s.id), "
      "(SELECT count(*) FROM events e WHERE e.session = s.id AND e.kind = 'onset'), s.display_json "
      "FROM sessions s JOIN participants p ON p.id = s.participant LEFT JOIN experiments x ON x.id = s.experiment "
      "WHERE p.experiment ") + kOfExperiment + " ORDER BY s.id",
      e.id, [&](const ResultRow& s) {
        const auto status = statuses.find(cell(s, 1));
        t.rows.push_back({e.id, cell(s, 0), cell(s, 1), cell(s, 2), cell(s, 3), cell(s, 4), cell(s, 5), cell(s, 6),
                          status == statuses.end() ? "" : status->second, cell(s, 7), cell(s, 8), cell(s, 9), cell(s, 10)});
      });
  return t;
}

// A table whose cells are the experiment id followed by the query's columns, as text.
DataTable queryTable(TableQueries& q, const std::string& experimentId, std::vector<std::string> header, const std::string& sql) {
  DataTable t;
  t.header = std::move(header);
  q.forEachRow(sql, experimentId, [&](const ResultRow& s) {
    std::vector<std::string> row = {experimentId};
    for (int c = 0; c + 1 < int(t.header.size()); ++c) row.push_back(cell(s, c));
    t.rows.push_back(std::move(row));
  });
  return t;
}

}  // namespace

std::string storedRealText(double value) {
  if (value == 0) return "0.0";  // SQLite stores -0.0 as 0
  char buf[64];
  sqlite3_snprintf(sizeof buf, buf, "%!.15g", value);
  return buf;
}

namespace store_tables {

DataTable exportTable(TableQueries& q, ExportTable table, const Experiment& e) {
  const std::string of = kOfExperiment;
  switch (table) {
    case ExportTable::Trials: return trialsTable(q, e);
    case ExportTable::Sessions: return sessionsTable(q, e);
    case ExportTable::Questionnaires:
      return queryTable(q, e.id, {"experiment", "participant", "questionnaire", "block", "item", "answer", "value", "session", "recorded_at"},
                        "SELECT p.participant, q.questionnaire, q.block, q.item, q.answer, q.value, q.session, q.recorded_at "
                        "FROM questionnaire_answers q JOIN participants p ON p.id = q.participant WHERE p.experiment " + of +
                            " ORDER BY p.slot, q.id");
    case ExportTable::Participants:
      return queryTable(q, e.id, {"experiment", "participant", "slot", "design_row", "between_cell", "block_order", "status", "assigned_at",
                                  "finished_at"},
                        "SELECT p.participant, a.slot, a.design_row, a.between_cell, a.block_order, a.status, a.assigned_at, "
                        "p.finished_at FROM assignments a JOIN participants p ON p.id = a.participant WHERE a.experiment " + of +
                            " ORDER BY a.slot, a.id");
    case ExportTable::Events:
      return queryTable(q, e.id, {"experiment", "participant", "session", "trial_sequence", "t_ns", "kind", "detail"},
                        "SELECT p.participant, e.session, t.sequence, e.t_ns, e.kind, e.detail FROM events e "
                        "JOIN sessions s ON s.id = e.session JOIN participants p ON p.id = s.participant "
                        "LEFT JOIN trials t ON t.id = e.trial WHERE p.experiment " + of + " ORDER BY e.id");
    case ExportTable::Info:
      return queryTable(q, e.id, {"experiment", "participant", "field", "value", "number", "session", "recorded_at"},
                        "SELECT p.participant, i.field, i.value, i.number, i.session, i.recorded_at FROM participant_info i "
                        "JOIN participants p ON p.id = i.participant WHERE p.experiment " + of + " ORDER BY p.id, i.id");
    case ExportTable::Consent:
      return queryTable(q, e.id, {"experiment", "participant", "decision", "session", "recorded_at"},
                        "SELECT p.participant, c.decision, c.session, c.recorded_at FROM consent c "
                        "JOIN participants p ON p.id = c.participant WHERE p.experiment " + of + " ORDER BY c.id");
  }
  throw StoreError("unknown export table");
}

std::vector<AnalysisRecord> analysisRecords(TableQueries& q, const std::string& experimentId, const std::string& dv) {
  const auto column = kDependentVariableSql.find(dv);
  if (column == kDependentVariableSql.end()) throw StoreError("unknown dependent variable '" + dv + "'");
  std::vector<AnalysisRecord> out;
  q.forEachRow("SELECT p.participant, t.levels_json, t.task_id, t.block, " + column->second + ", t.id, t.stimulus_sha256 FROM trials t "
               "JOIN participants p ON p.id = t.participant JOIN responses r ON r.trial = t.id "
               "WHERE p.experiment " + std::string(kOfExperiment) + " AND p.status != 'dropped' AND t.phase = 'test' AND " +
                   column->second + " IS NOT NULL ORDER BY p.id, t.sequence",
               experimentId, [&](const ResultRow& s) {
                 out.push_back({s.text(0), s.text(1), s.text(2), int(s.integer(3)), s.real(4), std::size_t(s.integer(5)), s.text(6)});
               });
  return out;
}

std::vector<std::map<std::string, int>> sessionModes(TableQueries& q, const std::string& experimentId) {
  std::vector<std::map<std::string, int>> out;
  std::int64_t last = -1;
  q.forEachRow("SELECT s.participant, s.mode, count(*) FROM sessions s JOIN participants p ON p.id = s.participant "
               "WHERE p.experiment " + std::string(kOfExperiment) + " GROUP BY s.participant, s.mode ORDER BY s.participant",
               experimentId, [&](const ResultRow& s) {
                 if (s.integer(0) != last) out.emplace_back(), last = s.integer(0);
                 out.back()[s.text(1)] = int(s.integer(2));
               });
  return out;
}

std::vector<StoredAnswer> formAnswers(TableQueries& q, const std::string& experimentId) {
  std::vector<StoredAnswer> out;
  q.forEachRow("SELECT p.participant, a.questionnaire, a.item, a.answer, a.value, a.id FROM questionnaire_answers a "
               "JOIN participants p ON p.id = a.participant WHERE p.experiment " + std::string(kOfExperiment) + " AND p.status != 'dropped' "
               "UNION ALL SELECT p.participant, 'info', i.field, i.value, i.number, i.id FROM participant_info i "
               "JOIN participants p ON p.id = i.participant WHERE p.experiment " + std::string(kOfExperiment) + " AND p.status != 'dropped' "
               "ORDER BY 2, 6",
               experimentId, [&](const ResultRow& s) {
                 const auto number = s.isNull(4) ? std::nullopt : std::optional<double>(s.real(4));
                 out.push_back({s.text(0), s.text(1), s.text(2), s.text(3), number, std::size_t(s.integer(5))});
               });
  return out;
}

// One file per stimulus sha256 and key: min() only names it in SQL both databases accept.
DataTable stimulusSummary(TableQueries& q, const std::string& experimentId) {
  DataTable t;
  t.header = {"condition", "task", "phase", "stimulus", "file", "sha256", "trials", "participants"};
  q.forEachRow("SELECT t.condition, t.task_id, t.phase, t.stimulus_key, min(t.stimulus_path), t.stimulus_sha256, COUNT(*), "
               "COUNT(DISTINCT t.participant) FROM trials t JOIN participants p ON p.id = t.participant "
               "WHERE p.experiment " + std::string(kOfExperiment) + " GROUP BY t.stimulus_sha256, t.stimulus_key, t.phase, t.condition, "
               "t.task_id ORDER BY t.phase DESC, t.condition, t.task_id, t.stimulus_key",
               experimentId, [&](const ResultRow& s) {
                 t.rows.push_back({s.text(0), s.text(1), s.text(2), s.text(3), s.text(4), s.text(5), cell(s, 6), cell(s, 7)});
               });
  return t;
}

// The file of the first test trial (lowest id) of each condition and task.
DataTable stimulusExamples(TableQueries& q, const std::string& experimentId) {
  DataTable t;
  t.header = {"condition", "task", "file"};
  q.forEachRow("SELECT t.condition, t.task_id, t.stimulus_path FROM trials t WHERE t.id IN (SELECT min(f.id) FROM trials f "
               "JOIN participants p ON p.id = f.participant WHERE p.experiment " + std::string(kOfExperiment) +
                   " AND f.phase = 'test' GROUP BY f.condition, f.task_id) ORDER BY t.condition, t.task_id",
               experimentId, [&](const ResultRow& s) { t.rows.push_back({s.text(0), s.text(1), s.text(2)}); });
  return t;
}

DataTable liveTrials(TableQueries& q, const std::string& experimentId) {
  DataTable t;
  t.header = {"participant", "sequence", "phase", "task_id", "frames"};
  q.forEachRow("SELECT p.participant, t.sequence, t.phase, t.task_id, COUNT(*) FROM events e JOIN trials t ON t.id = e.trial "
               "JOIN participants p ON p.id = t.participant WHERE e.kind = 'frame' AND p.experiment " + std::string(kOfExperiment) +
                   " GROUP BY p.id, p.participant, t.sequence, t.phase, t.task_id ORDER BY p.id, t.sequence",
               experimentId, [&](const ResultRow& s) { t.rows.push_back({s.text(0), s.text(1), s.text(2), s.text(3), s.text(4)}); });
  return t;
}

DataTable trialFrames(TableQueries& q, std::int64_t trial) {
  DataTable t;
  t.header = {"session", "t_ns", "detail"};
  q.forEachRow("SELECT e.session, e.t_ns, e.detail FROM events e WHERE e.trial = CAST(?1 AS INTEGER) AND e.kind = 'frame' ORDER BY e.id",
               std::to_string(trial), [&](const ResultRow& s) { t.rows.push_back({s.text(0), s.text(1), s.text(2)}); });
  return t;
}

}  // namespace store_tables

}  // namespace tlab::study
