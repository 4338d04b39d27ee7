#include "study/csv_export.hpp"

#include <filesystem>

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

std::string exportTrials(SessionStore& store, const StoredExperiment& stored, const std::filesystem::path& dir) {
  std::vector<std::string> header = {"experiment", "participant", "slot", "participant_status", "sequence", "phase", "block", "condition"};
  for (const auto& f : stored.experiment.factors) header.push_back(f.name);
  header.insert(header.end(), {"task_id", "task", "trial", "question", "answer_kind", "truth", "responded", "raw_answer", "answered",
                               "correct", "score", "partial_credit", "error", "rt_seconds", "time_limit", "onset_ns",
                               "response_ns", "note", "stimulus_path", "stimulus_sha256", "probe_seed", "session", "recorded_at"});
  CsvWriter csv(header);
  Statement s = store.database().prepare(
      "SELECT p.participant, p.slot, p.status, t.sequence, t.phase, t.block, t.condition, t.levels_json, t.task_id, t.task, "
      "t.trial, t.question, t.answer_kind, t.truth_json, r.id IS NOT NULL, r.raw_answer, r.answered, r.correct, r.score, "
      "r.partial_credit, r.error, r.rt_seconds, t.time_limit, r.onset_ns, r.response_ns, r.note, t.stimulus_path, "
      "t.stimulus_sha256, t.probe_seed, r.session, r.recorded_at FROM trials t JOIN participants p ON p.id = t.participant "
      "LEFT JOIN responses r ON r.trial = t.id WHERE p.experiment = ?1 ORDER BY p.slot, p.id, t.sequence");
  s.bind(1, stored.row);
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
    for (int c = 23; c <= 30; ++c) row.push_back(c == 28 ? std::to_string(std::uint64_t(s.integer(c))) : cell(s, c));
    csv.row(row);
  }
  const std::string path = (dir / "trials.csv").string();
  csv.write(path);
  return path;
}

std::string exportQuery(SessionStore& store, const StoredExperiment& stored, const std::filesystem::path& path,
                        const std::vector<std::string>& header, const std::string& sql) {
  CsvWriter csv(header);
  Statement s = store.database().prepare(sql);
  s.bind(1, stored.row);
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
  std::filesystem::create_directories(dir);
  std::vector<std::string> written;
  written.push_back(exportTrials(store, stored, dir));
  written.push_back(exportQuery(store, stored, dir / "questionnaires.csv",
                                {"experiment", "participant", "questionnaire", "block", "item", "value", "session", "recorded_at"},
                                "SELECT p.participant, q.questionnaire, q.block, q.item, q.value, q.session, q.recorded_at "
                                "FROM questionnaire_answers q JOIN participants p ON p.id = q.participant WHERE p.experiment = ?1 "
                                "ORDER BY p.slot, q.id"));
  written.push_back(exportQuery(store, stored, dir / "participants.csv",
                                {"experiment", "participant", "slot", "design_row", "between_cell", "block_order", "status",
                                 "assigned_at", "finished_at"},
                                "SELECT p.participant, a.slot, a.design_row, a.between_cell, a.block_order, a.status, a.assigned_at, "
                                "p.finished_at FROM assignments a JOIN participants p ON p.id = a.participant WHERE a.experiment = ?1 "
                                "ORDER BY a.slot, a.id"));
  written.push_back(exportQuery(store, stored, dir / "events.csv",
                                {"experiment", "participant", "session", "trial_sequence", "t_ns", "kind", "detail"},
                                "SELECT p.participant, e.session, t.sequence, e.t_ns, e.kind, e.detail FROM events e "
                                "JOIN sessions s ON s.id = e.session JOIN participants p ON p.id = s.participant "
                                "LEFT JOIN trials t ON t.id = e.trial WHERE p.experiment = ?1 ORDER BY e.id"));
  return written;
}

}  // namespace tlab::study
