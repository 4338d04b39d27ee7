#include "study/serve/request_checks.hpp"

#include <algorithm>
#include <regex>
#include <string_view>

namespace tlab::study {

bool validParticipantId(const std::string& id) {
  static const std::regex allowed("[A-Za-z0-9_.@-]{1,128}");
  return std::regex_match(id, allowed);
}

std::string browserKey(const std::string& cookieHeader) {
  constexpr std::string_view name = "tlab-browser=";
  std::size_t at = 0;
  while (at <= cookieHeader.size()) {  // "a=1; tlab-browser=KEY; b=2": each pair, spaces around it dropped
    const std::size_t end = std::min(cookieHeader.find(';', at), cookieHeader.size());
    std::string_view pair(cookieHeader.data() + at, end - at);
    while (!pair.empty() && pair.front() == ' ') pair.remove_prefix(1);
    while (!pair.empty() && pair.back() == ' ') pair.remove_suffix(1);
    if (pair.substr(0, name.size()) == name) {
      const std::string_view key = pair.substr(name.size());
      const bool hex = key.size() == 32 && key.find_first_not_of("0123456789abcdef") == std::string_view::npos;
      return hex ? std::string(key) : "";
    }
    at = end + 1;
  }
  return "";
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
