#pragma once
// A participant's page as the serve tests drive it: the JSON API of `tlab serve` through
// cpp-httplib's client (study/serve/study_server.hpp documents the routes).
#include <httplib.h>

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace tlab::testing {

struct Reply {
  int status = 0;
  nlohmann::json body;
};

class PageClient {
 public:
  explicit PageClient(int port) : http_("127.0.0.1", port) { http_.set_read_timeout(30, 0); }

  // GET /s/STUDY?QUERY: the status and the redirect's token ("" when none).
  std::pair<int, std::string> arrive(const std::string& study, const std::string& query) {
    const auto r = http_.Get(("/s/" + study + "?" + query).c_str());
    if (!r) throw std::runtime_error("no reply to the arrival");
    const std::string location = r->get_header_value("Location");
    return {r->status, location.rfind("/p/", 0) == 0 ? location.substr(3) : ""};
  }
  Reply get(const std::string& path) { return parse(http_.Get(path.c_str())); }
  Reply post(const std::string& path, const std::string& body, const char* type = "application/json") {
    return parse(http_.Post(path.c_str(), body, type));
  }
  Reply api(const std::string& token, const std::string& what, const nlohmann::json& body) { return post("/api/" + token + "/" + what, body.dump()); }
  Reply screen(const std::string& token) { return get("/api/" + token + "/screen"); }
  httplib::Result raw(const std::string& path) { return http_.Get(path.c_str()); }

 private:
  static Reply parse(const httplib::Result& r) {
    if (!r) throw std::runtime_error("no reply from tlab serve");
    return {r->status, nlohmann::json::parse(r->body, nullptr, false)};
  }
  httplib::Client http_;
};

// The reply a participant gives to a screen that is not a trial.
inline nlohmann::json continueReply(const nlohmann::json& screen) {
  const std::string kind = screen["kind"];
  nlohmann::json r{{"seq", screen["seq"]}};
  if (kind == "consent") r.update({{"type", "consent"}, {"accepted", true}});
  else if (kind == "form") r.update({{"type", "form"}, {"values", nlohmann::json::array()}});
  else r["type"] = "continue";
  if (kind == "form")
    for (std::size_t i = 0; i < screen["fields"].size(); ++i) r["values"].push_back("3");
  return r;
}

}  // namespace tlab::testing
