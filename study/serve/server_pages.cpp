#include "study/serve/server_pages.hpp"

#include <stdexcept>

#include "analysis/number_format.hpp"

namespace tlab::study {

namespace {

std::string document(const std::string& title, const std::string& body) {
  return "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width\">"
         "<title>" + analysis::escapeHtml(title) + "</title><link rel=\"stylesheet\" href=\"/static/participant.css\"></head><body><main>" + body +
         "</main></body></html>\n";
}

std::string cell(const nlohmann::json& v) { return "<td>" + analysis::escapeHtml(v.is_string() ? v.get<std::string>() : v.dump()) + "</td>"; }

std::string actionForm(const std::string& action, const std::string& participant, const std::string& token, const std::string& extra) {
  return "<form method=\"post\" action=\"/admin/" + action + "\"><input type=\"hidden\" name=\"token\" value=\"" + analysis::escapeHtml(token) +
         "\"><input type=\"hidden\" name=\"participant\" value=\"" + analysis::escapeHtml(participant) + "\">" + extra + "<button>" + action +
         "</button></form>";
}

}  // namespace

std::string messagePage(const std::string& title, const std::string& text) {
  return document(title, "<h1>" + analysis::escapeHtml(title) + "</h1><p>" + analysis::escapeHtml(text) + "</p>");
}

std::string completionPage(const std::string& title, const std::string& text, const std::string& code, const std::string& url) {
  std::string body = "<h1>" + analysis::escapeHtml(title) + "</h1><p>" + analysis::escapeHtml(text) + "</p>";
  if (!code.empty()) body += "<p>Your completion code: <strong id=\"completion-code\">" + analysis::escapeHtml(code) + "</strong></p>";
  if (!url.empty())
    body += "<p><a id=\"completion-link\" href=\"" + analysis::escapeHtml(url) + "\">Return to the study platform to confirm completion</a></p>";
  return document(title, body);
}

std::string adminPage(const nlohmann::json& status, const std::string& adminToken) {
  std::string body = "<h1>" + analysis::escapeHtml(status["experiment"].get<std::string>()) + " — admin</h1>";
  body += "<p>" + analysis::escapeHtml(status["summary"].get<std::string>()) + "</p>";
  body += "<h2>Slots</h2><table><tr><th>slot</th><th>participant</th><th>status</th><th>answered</th><th>session</th><th></th></tr>";
  for (const auto& s : status["slots"]) {
    const std::string participant = s["participant"].get<std::string>();
    const bool active = s["status"] == "active";
    body += "<tr>" + cell(s["slot"]) + cell(participant) + cell(s["status"]) + cell(s["answered"]) + cell(s["session"]) + "<td>" +
            (active ? actionForm("drop", participant, adminToken, "") +
                          actionForm("extend", participant, adminToken, "<input name=\"minutes\" value=\"30\" size=\"3\"> min ")
                    : "") +
            "</td></tr>";
  }
  body += "</table>";
  body += "<h2>Arrived, not enrolled yet</h2><p>At the welcome or the consent: a newcomer gets a slot once they agree.</p>";
  body += "<table><tr><th>participant</th><th>session</th></tr>";
  for (const auto& a : status["arrived"]) body += "<tr>" + cell(a["participant"]) + cell(a["session"]) + "</tr>";
  body += "</table>";
  return document("admin", body);
}

}  // namespace tlab::study
