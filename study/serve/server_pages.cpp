#include "study/serve/server_pages.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "analysis/number_format.hpp"
#include "study/serve/web_assets.hpp"

namespace tlab::study {

namespace {

std::string document(const std::string& title, const std::string& body, const std::string& head = "", const std::string& language = "en") {
  return "<!doctype html><html lang=\"" + analysis::escapeHtml(language) + "\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width\">" + head +
         "<title>" + analysis::escapeHtml(title) + "</title><link rel=\"stylesheet\" href=\"/static/participant.css\"></head><body><main>" + body +
         "</main></body></html>\n";
}

std::string cell(const nlohmann::json& v) { return "<td>" + analysis::escapeHtml(v.is_string() ? v.get<std::string>() : v.dump()) + "</td>"; }

std::string actionForm(const std::string& action, const std::string& participant, const std::string& token, const std::string& extra,
                       const char* method = "post") {
  return "<form method=\"" + std::string(method) + "\" action=\"/admin/" + action + "\"><input type=\"hidden\" name=\"token\" value=\"" + analysis::escapeHtml(token) +
         "\"><input type=\"hidden\" name=\"participant\" value=\"" + analysis::escapeHtml(participant) + "\">" + extra + "<button>" + action +
         "</button></form>";
}

}  // namespace

std::string messagePage(const std::string& title, const std::string& text, const std::string& language) {
  return document(title, "<h1>" + analysis::escapeHtml(title) + "</h1><p>" + analysis::escapeHtml(text) + "</p>", "", language);
}

std::string completionPage(const std::string& title, const std::string& text, const std::string& code, const std::string& url,
                           const ParticipantTexts& texts) {
  std::string body = "<h1>" + analysis::escapeHtml(title) + "</h1><p>" + analysis::escapeHtml(text) + "</p>";
  if (!code.empty())
    body += "<p>" + analysis::escapeHtml(texts.text("end.completion_code")) + " <strong id=\"completion-code\">" + analysis::escapeHtml(code) + "</strong></p>";
  if (!url.empty())
    body += "<p><a id=\"completion-link\" href=\"" + analysis::escapeHtml(url) + "\">" + analysis::escapeHtml(texts.text("end.return_link")) + "</a></p>";
  return document(title, body, "", texts.language());
}

namespace {

// The whole table as JSON for the page's <script type="application/json">: "<" written as \u003c,
// so that no text can close the script element.
std::string textsJson(const ParticipantTexts& texts) {
  std::string out;
  for (const char c : nlohmann::json(texts.entries()).dump()) out += c == '<' ? std::string("\\u003c") : std::string(1, c);
  return out;
}

}  // namespace

std::string participantPage(const ParticipantTexts& texts) {
  const std::string_view html = webAsset("participant.html");
  std::string out;
  for (std::size_t i = 0; i < html.size();) {
    const std::size_t open = html.find("{{", i);
    if (open == std::string_view::npos) {
      out += html.substr(i);
      break;
    }
    const std::size_t close = html.find("}}", open);
    if (close == std::string_view::npos) throw std::logic_error("participant.html: an unclosed {{");
    const std::string key(html.substr(open + 2, close - open - 2));
    out += html.substr(i, open - i);
    if (key == "texts") out += textsJson(texts);
    else out += analysis::escapeHtml(key == "language" ? texts.language() : texts.text(key));
    i = close + 2;
  }
  return out;
}

std::string durationCell(const nlohmann::json& seconds) {
  if (!seconds.is_number()) return "";
  const long t = std::lround(seconds.get<double>());
  char text[48];
  if (t < 60) std::snprintf(text, sizeof text, "%ld s", t);
  else if (t < 3600) std::snprintf(text, sizeof text, "%ld min %02ld s", t / 60, t % 60);
  else std::snprintf(text, sizeof text, "%ld h %02ld min", t / 3600, (t % 3600) / 60);
  return text;
}

std::string adminPage(const nlohmann::json& status, const std::string& adminToken) {
  std::string body = "<h1>" + analysis::escapeHtml(status["experiment"].get<std::string>()) + " — admin</h1>";
  body += "<p id=\"summary\">" + analysis::escapeHtml(status["summary"].get<std::string>()) + "</p>";
  const int target = status["target"].get<int>(), finished = status["finished"].get<int>();
  body += "<p><progress id=\"progress\" max=\"" + std::to_string(target) + "\" value=\"" + std::to_string(std::min(finished, target)) + "\"></progress> " +
          std::to_string(finished) + " / " + std::to_string(target) + " finished. This page reloads every 10 s; idle: no request from the "
          "page for 45 s (its browser is likely closed); such a session times out after the experiment's timeout_minutes.</p>";
  body += "<h2>Slots</h2><table id=\"slots\"><tr><th>slot</th><th>participant</th><th>status</th><th>session</th><th>screen</th><th>elapsed</th>"
          "<th>idle</th><th>answered (test)</th><th>missing (test)</th><th>trials done</th><th></th></tr>";
  for (const auto& s : status["slots"]) {
    const std::string participant = s["participant"].get<std::string>();
    const bool active = s["status"] == "active";
    body += "<tr>" + cell(s["slot"]) + cell(participant) + cell(s["status"]) + cell(s["session"]) + cell(s["screen"]) + cell(durationCell(s["elapsed_s"])) +
            cell(durationCell(s["idle_s"])) + cell(s["answered"]) + cell(s["missing"]) + cell(s["trials"]) + "<td>" +
            (active ? actionForm("drop", participant, adminToken, "", "get") +
                          actionForm("extend", participant, adminToken, "<input name=\"minutes\" value=\"30\" size=\"3\"> min ")
                    : "") +
            "</td></tr>";
  }
  body += "</table>";
  body += "<h2>Arrived, not enrolled yet</h2><p>At the welcome or the consent: a newcomer gets a slot once they agree.</p>";
  body += "<table id=\"arrived\"><tr><th>participant</th><th>session</th><th>screen</th><th>elapsed</th><th>idle</th></tr>";
  for (const auto& a : status["arrived"])
    body += "<tr>" + cell(a["participant"]) + cell(a["session"]) + cell(a["screen"]) + cell(durationCell(a["elapsed_s"])) + cell(durationCell(a["idle_s"])) + "</tr>";
  body += "</table>";
  return document("admin", body, "<meta http-equiv=\"refresh\" content=\"10\">");
}

std::string dropConfirmationPage(const std::string& participant, const std::string& adminToken) {
  const std::string who = analysis::escapeHtml(participant);
  return document("Drop " + participant + "?",
                  "<h1>Drop " + who + "?</h1><p>Their session ends at once and their slot goes to the next newcomer; what they answered "
                  "stays stored. This cannot be undone.</p>" +
                      actionForm("drop", participant, adminToken, "") + "<p><a href=\"/admin?token=" + analysis::escapeHtml(adminToken) +
                      "\">Cancel: back to the admin page</a></p>");
}

}  // namespace tlab::study
