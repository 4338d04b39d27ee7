#pragma once
// A participant's page as the serve tests drive it: the JSON API of `tlab serve` through
// cpp-httplib's client (study/serve/study_server.hpp documents the routes).
#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

namespace tlab::testing {

struct Reply {
  int status = 0;
  nlohmann::json body;
};

class PageClient {
 public:
  // `cookie`: the Cookie header a browser would send ("tlab-browser=KEY"); none by default.
  explicit PageClient(int port, const std::string& cookie = "") : http_("127.0.0.1", port) {
    http_.set_read_timeout(30, 0);
    if (!cookie.empty()) http_.set_default_headers({{"Cookie", cookie}});
  }

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

// A valid answer to one form field: the middle of a scale, the first option, a number in range.
inline std::string fieldAnswer(const nlohmann::json& field) {
  const std::string kind = field["kind"];
  if (kind == "likert") return std::to_string((field["points"].get<int>() + 1) / 2);
  if (kind == "choice") return field["options"][0];
  if (kind == "number") return std::to_string(int(std::max(30.0, field["min"].get<double>())));
  return "fine";
}

// The reply a participant gives to a screen that is not a trial.
inline nlohmann::json continueReply(const nlohmann::json& screen) {
  const std::string kind = screen["kind"];
  nlohmann::json r{{"seq", screen["seq"]}};
  if (kind == "consent") r.update({{"type", "consent"}, {"accepted", true}});
  else if (kind == "calibration")  // the card sized with one adjustment: 323.6 CSS px = 8.56 cm at 1x
    r.update({{"type", "calibration"}, {"skipped", false}, {"px_per_cm", 37.8}, {"card_css_px", 323.6}, {"device_pixel_ratio", 1}, {"adjustments", 1}});
  else if (kind == "form") r.update({{"type", "form"}, {"values", nlohmann::json::array()}});
  else r["type"] = "continue";
  if (kind == "form")
    for (const auto& field : screen["fields"]) r["values"].push_back(fieldAnswer(field));
  return r;
}

// What a page reports of its display.
inline nlohmann::json display() { return {{"screen_width", 1920}, {"screen_height", 1080}, {"device_pixel_ratio", 1}, {"refresh_hz", 60}}; }

struct Walk {
  std::vector<nlohmann::json> screens;
  int answered = 0;
};

// Answers every screen from `screen` on until `stopAfter` trials were answered (or the end);
// trial answers alternate 1, 2, 1, ... with an RT of 850 ms.
inline Walk walk(PageClient& page, const std::string& token, nlohmann::json screen, int stopAfter = 1 << 20) {
  Walk w;
  for (int step = 0; step < 200; ++step) {
    w.screens.push_back(screen);
    const std::string kind = screen["kind"];
    if (kind == "end" || kind == "error") break;
    if (kind == "wait") {
      screen = page.screen(token).body;
      continue;
    }
    if (kind == "break")  // the participant waits as long as the break asks (an earlier press is ignored)
      std::this_thread::sleep_for(std::chrono::duration<double>(screen["min_seconds"].get<double>() + 0.3));
    if (kind != "trial") {
      screen = page.api(token, "reply", continueReply(screen)).body;
      continue;
    }
    if (w.answered == stopAfter) break;
    EXPECT_EQ(page.api(token, "reply", {{"seq", screen["seq"]}, {"type", "onset"}, {"painted_ms", 10.5}}).status, 200);
    const Reply r = page.api(token, "reply", {{"seq", screen["seq"]}, {"type", "answer"}, {"answer", 1 + w.answered % 2}, {"rt_ms", 850.0},
                                                       {"painted_ms", 10.5}, {"input_ms", 860.5}});
    EXPECT_EQ(r.status, 200) << r.body.dump();
    if (r.body.value("kind", "") != "error") ++w.answered;
    screen = r.body;
  }
  return w;
}

// One table of `tlab export DB --csv` (DB: a file or a postgresql:// URL).
inline std::vector<std::vector<std::string>> exportedTable(const std::string& db, const std::filesystem::path& dir, const std::string& table) {
  const auto csv = dir / "csv";
  std::filesystem::remove_all(csv);
  const auto r = runCommand(commandLine({TLAB_EXE, "export", db, "--csv", csv.string()}));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return parseCsv(readText((csv / (table + ".csv")).string()));
}

inline std::size_t column(const std::vector<std::vector<std::string>>& rows, const std::string& name) {
  for (std::size_t i = 0; i < rows.front().size(); ++i)
    if (rows.front()[i] == name) return i;
  throw std::runtime_error("no column " + name);
}

}  // namespace tlab::testing
