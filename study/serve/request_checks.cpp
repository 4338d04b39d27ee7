#include "study/serve/request_checks.hpp"

#include <regex>

namespace tlab::study {

bool validParticipantId(const std::string& id) {
  static const std::regex allowed("[A-Za-z0-9_.@-]{1,128}");
  return std::regex_match(id, allowed);
}

std::optional<std::string> checkDisplay(const nlohmann::json& body) {
  if (body.size() > 40) return "too many fields";
  for (const auto& [key, value] : body.items()) {
    if (key.size() > 40) return "a field name is too long";
    if (!(value.is_number() || value.is_boolean() || (value.is_string() && value.get<std::string>().size() <= 400))) return "field '" + key + "': expected a number or a short text";
  }
  return std::nullopt;
}

std::string requestText(const std::string& raw, std::size_t maxBytes) {
  return nlohmann::json::parse(jsonText(raw.substr(0, maxBytes))).get<std::string>();
}

nlohmann::json arrivalRecord(const std::string& participant, const std::string& userAgent,
                             const std::vector<std::pair<std::string, std::string>>& linkParameters) {
  nlohmann::json arrival{{"participant", participant}, {"user_agent", requestText(userAgent, 400)}};
  for (const auto& [name, value] : linkParameters) arrival[name] = requestText(value, 200);
  return arrival;
}

std::string jsonText(const nlohmann::json& value) { return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }

}  // namespace tlab::study
