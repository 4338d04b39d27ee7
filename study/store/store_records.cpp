#include "study/store/store_records.hpp"

#include <nlohmann/json.hpp>

#include "core/sha256.hpp"

namespace tlab::study {

std::optional<ExperimentVersion> versionWithText(const std::vector<ExperimentVersion>& versions, const std::string& text) {
  const std::string hash = core::sha256Hex(text);
  for (const auto& v : versions)
    if (v.sha256 == hash) return v;
  return std::nullopt;
}

std::optional<std::int64_t> newestVersionRow(const std::vector<ExperimentVersion>& versions) {
  if (versions.empty()) return std::nullopt;
  return versions.back().row;
}

std::string blockOrderText(const Design& design, const SlotDesign& slot) {
  std::string text;
  for (std::size_t b = 0; b < slot.blocks.size(); ++b) text += (b ? " | " : "") + design.describe(slot.blocks[b]);
  return text;
}

std::string onsetDetail(const std::string& detail, int showing) {
  nlohmann::json d = nlohmann::json::parse(detail.empty() ? "{}" : detail, nullptr, false);
  if (!d.is_object()) d = nlohmann::json{{"detail", detail}};
  d["showing"] = showing;
  if (showing > 1) d["repeat"] = "shown again after an interruption";
  return d.dump();
}

std::string enrolledElsewhereMessage(const std::string& location, const std::string& participant) {
  return location + ": participant '" + participant + "' was enrolled by another station a moment ago; continue with --resume "
         "once that station has stopped, or use another participant id";
}

std::string sessionConflictMessage(const std::string& location, const std::string& participant, std::int64_t session,
                                   const std::string& station, const std::string& startedAt, const std::string& state) {
  return location + ": participant '" + participant + "' is in session " + std::to_string(session) + " at station " + station +
         " (started " + startedAt + (state == "unknown" ? ", another machine" : "") +
         "); let that session finish, or stop it and continue there with --resume";
}

std::string duplicateResponseMessage(const std::string& location, std::int64_t trial) {
  return location + ": trial " + std::to_string(trial) + " already has a response: is this participant's session running at another station too?";
}

}  // namespace tlab::study
