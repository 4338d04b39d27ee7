#include "study/csv_export.hpp"

#include <filesystem>
#include <map>

#include <nlohmann/json.hpp>

#include "renderer/image/image.hpp"

namespace tlab::study {

namespace {

class CsvWriter {
 public:
  explicit CsvWriter(std::vector<std::string> header) : columns_(header.size()) { row(header); }
  void row(const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) text_ += (i ? "," : "") + csvField(cells[i]);
    text_ += "\r\n";
  }
  std::size_t columns() const { return columns_; }
  void write(const std::string& path) const {
    render::writeFileAtomically(path, std::vector<std::uint8_t>(text_.begin(), text_.end()));
  }

 private:
  std::size_t columns_;
  std::string text_;
};

std::string cell(const Statement& s, int column) {
  if (s.isNull(column)) return "";
  return s.text(column);
}

std::string numberCell(const Statement& s, int column) {
  if (s.isNull(column)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", s.real(column));
  return buf;
}

// Every participant of every version of the experiment (?1 is the experiment id).
constexpr const char* kOfExperiment = "IN (SELECT id FROM experiments WHERE experiment_id = ?1)";

// Session id → "finished", "closed", "storage error", "interrupted", "interrupted, resumed by
// session N" or "running" (its station's process is alive on this machine).
std::map<std::string, std::string> sessionStatuses(SessionStore& store) {
  Statement s = store.database().prepare(
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

std::string exportTrials(SessionStore& store, const StoredExperiment& stored, const std::filesystem::path& dir) {
  std::vector<std::string> header = {"experiment", "participant", "slot", "participant_status", "sequence", "phase", "block", "condition"};
  for (const auto& f : stored.experiment.factors) header.push_back(f.name);
  header.insert(header.end(), {"task_id", "task", "trial", "question", "answer_kind", "truth", "responded", "raw_answer", "answered",
                               "correct", "score", "partial_credit", "error", "rt_seconds", "time_limit", "onset_ns",
                               "response_ns", "note", "stimulus_path", "stimulus_sha256", "probe_seed", "session", "recorded_at",
                               "experiment_version", "session_status", "showings"});
  CsvWriter csv(header);
  const auto statuses = sessionStatuses(store);
  Statement s = store.database().prepare(
      std::string("SELECT p.participant, p.slot, p.status, t.sequence, t.phase, t.block, t.condition, t.levels_json, t.task_id, t.task, "
      "t.trial, t.question, t.answer_kind, t.truth_json, r.id IS NOT NULL, r.raw_answer, r.answered, r.correct, r.score, "
      "r.partial_credit, r.error, r.rt_seconds, t.time_limit, r.onset_ns, r.response_ns, r.note, t.stimulus_path, "
      "t.stimulus_sha256, t.probe_seed, r.session, r.recorded_at, x.version, "
      "(SELECT count(*) FROM events e WHERE e.trial = t.id AND e.kind = 'onset') "
      "FROM trials t JOIN participants p ON p.id = t.participant "
      "LEFT JOIN responses r ON r.trial = t.id LEFT JOIN sessions ss ON ss.id = r.session "
      "LEFT JOIN experiments x ON x.id = ss.experiment WHERE p.experiment ") + kOfExperiment +
      " ORDER BY p.slot, p.id, t.sequence");
  s.bind(1, stored.experiment.id);
  while (s.step()) {
    std::vector<std::string> row = {stored.experiment.id, cell(s, 0), cell(s, 1), cell(s, 2), cell(s, 3), cell(s, 4), cell(s, 5), cell(s, 6)};
    const auto levels = nlohmann::json::parse(s.text(7));
    for (const auto& f : stored.experiment.factors) row.push_back(levels.value(f.name, std::string()));
    for (int c = 8; c <= 13; ++c) row.push_back(cell(s, c));
    row.push_back(s.integer(14) ? "1" : "0");
    row.push_back(cell(s, 15));
    row.push_back(cell(s, 16));
    row.push_back(cell(s, 17));
    for (int c = 18; c <= 22; ++c) row.push_back(numberCell(s, c));
    for (int c = 23; c <= 27; ++c) row.push_back(cell(s, c));
    // A 64-bit seed above 2^53 is not a double: "seed:" keeps R (read.csv) and pandas from reading it as a number.
    row.push_back("seed:" + std::to_string(std::uint64_t(s.integer(28))));
    row.push_back(cell(s, 29));
    row.push_back(cell(s, 30));
    row.push_back(cell(s, 31));
    const auto status = statuses.find(cell(s, 29));
    row.push_back(status == statuses.end() ? "" : status->second);
    row.push_back(cell(s, 32));
    csv.row(row);
  }
  const std::string path = (dir / "trials.csv").string();
  csv.write(path);
  return path;
}

std::string exportSessions(SessionStore& store, const StoredExperiment& stored, const std::filesystem::path& dir) {
  CsvWriter csv({"experiment", "participant", "session", "experiment_version", "mode", "station", "started_at", "ended_at",
                 "status", "resumed_by", "responses", "onsets"});
  const auto statuses = sessionStatuses(store);
  Statement s = store.database().prepare(
      std::string("SELECT p.participant, s.id, x.version, s.mode, s.station, s.started_at, s.ended_at, s.resumed_by, "
      "(SELECT count(*) FROM responses r WHERE r.session = s.id), "
      "(SELECT count(*) FROM events e WHERE e.session = s.id AND e.kind = 'onset') "
      "FROM sessions s JOIN participants p ON p.id = s.participant LEFT JOIN experiments x ON x.id = s.experiment "
      "WHERE p.experiment ") + kOfExperiment + " ORDER BY s.id");
  s.bind(1, stored.experiment.id);
  while (s.step()) {
    const auto status = statuses.find(cell(s, 1));
    csv.row({stored.experiment.id, cell(s, 0), cell(s, 1), cell(s, 2), cell(s, 3), cell(s, 4), cell(s, 5), cell(s, 6),
             status == statuses.end() ? "" : status->second, cell(s, 7), cell(s, 8), cell(s, 9)});
  }
  const std::string path = (dir / "sessions.csv").string();
  csv.write(path);
  return path;
}

std::string exportQuery(SessionStore& store, const StoredExperiment& stored, const std::filesystem::path& path,
                        const std::vector<std::string>& header, const std::string& sql) {
  CsvWriter csv(header);
  Statement s = store.database().prepare(sql);
  s.bind(1, stored.experiment.id);
  while (s.step()) {
    std::vector<std::string> row = {stored.experiment.id};
    for (int c = 0; c + 1 < int(header.size()); ++c) row.push_back(cell(s, c));
    csv.row(row);
  }
  csv.write(path.string());
  return path.string();
}

}  // namespace

std::string csvField(const std::string& text) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' ' || text.front() == '\t' || text.back() == '\t'));
  if (!quote) return text;
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<std::string> exportCsv(SessionStore& store, const StoredExperiment& stored, const std::string& directory) {
  const std::filesystem::path dir(directory);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw StoreError(directory + ": cannot create the export folder (" + ec.message() + "): choose a writable folder");
  std::vector<std::string> written;
  written.push_back(exportTrials(store, stored, dir));
  written.push_back(exportSessions(store, stored, dir));
  written.push_back(exportQuery(store, stored, dir / "questionnaires.csv",
                                {"experiment", "participant", "questionnaire", "block", "item", "value", "session", "recorded_at"},
                                "SELECT p.participant, q.questionnaire, q.block, q.item, q.value, q.session, q.recorded_at "
                                "FROM questionnaire_answers q JOIN participants p ON p.id = q.participant WHERE p.experiment " +
                                    std::string(kOfExperiment) + " ORDER BY p.slot, q.id"));
  written.push_back(exportQuery(store, stored, dir / "participants.csv",
                                {"experiment", "participant", "slot", "design_row", "between_cell", "block_order", "status",
                                 "assigned_at", "finished_at"},
                                "SELECT p.participant, a.slot, a.design_row, a.between_cell, a.block_order, a.status, a.assigned_at, "
                                "p.finished_at FROM assignments a JOIN participants p ON p.id = a.participant WHERE a.experiment " +
                                    std::string(kOfExperiment) + " ORDER BY a.slot, a.id"));
  written.push_back(exportQuery(store, stored, dir / "events.csv",
                                {"experiment", "participant", "session", "trial_sequence", "t_ns", "kind", "detail"},
                                "SELECT p.participant, e.session, t.sequence, e.t_ns, e.kind, e.detail FROM events e "
                                "JOIN sessions s ON s.id = e.session JOIN participants p ON p.id = s.participant "
                                "LEFT JOIN trials t ON t.id = e.trial WHERE p.experiment " + std::string(kOfExperiment) + " ORDER BY e.id"));
  return written;
}

}  // namespace tlab::study
