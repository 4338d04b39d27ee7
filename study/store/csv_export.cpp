#include "study/store/csv_export.hpp"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/image.hpp"

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
    core::writeFileAtomically(path, std::vector<std::uint8_t>(text_.begin(), text_.end()));
  }

 private:
  std::size_t columns_;
  std::string text_;
};

// Writes one exported table as `dir/name`.
std::string writeTable(const DataTable& table, const std::filesystem::path& dir, const std::string& name) {
  CsvWriter csv(table.header);
  for (const auto& row : table.rows) csv.row(row);
  const std::string path = (dir / name).string();
  csv.write(path);
  return path;
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

std::vector<std::string> exportCsv(Store& store, const StoredExperiment& stored, const std::string& directory) {
  const std::filesystem::path dir(directory);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw StoreError(directory + ": cannot create the export folder (" + ec.message() + "): choose a writable folder");
  const Experiment& e = stored.experiment;
  return {writeTable(store.exportTable(ExportTable::Trials, e), dir, "trials.csv"),
          writeTable(store.exportTable(ExportTable::Sessions, e), dir, "sessions.csv"),
          writeTable(store.exportTable(ExportTable::Questionnaires, e), dir, "questionnaires.csv"),
          writeTable(store.exportTable(ExportTable::Participants, e), dir, "participants.csv"),
          writeTable(store.exportTable(ExportTable::Events, e), dir, "events.csv"),
          writeTable(store.exportTable(ExportTable::Info, e), dir, "participant_info.csv"),
          writeTable(store.exportTable(ExportTable::Consent, e), dir, "consent.csv")};
}

}  // namespace tlab::study
