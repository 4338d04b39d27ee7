#pragma once
// Small server-made pages: a message page (a link that is wrong, a participant who already
// finished) and the admin page, with every text HTML-escaped.
#include <string>

#include <nlohmann/json.hpp>

#include "study/design/participant_texts.hpp"

namespace tlab::study {

// `language`: the page's lang attribute (the participants' pages are in the experiment's language).
std::string messagePage(const std::string& title, const std::string& text, const std::string& language = "en");
// A message page that also shows the completion code and the link back to the platform (a
// participant who finished and opens the link again); either may be empty.
std::string completionPage(const std::string& title, const std::string& text, const std::string& code, const std::string& url,
                           const ParticipantTexts& texts);
// The participant page (web/participant.html) with each {{key}} replaced by the key's text and
// {{language}} by the language and {{texts}} by the whole table as JSON (which participant.js
// reads): the page's words come from the participant text table.
std::string participantPage(const ParticipantTexts& texts);
// The admin page for status() (study/serve/study_server_admin.cpp), with drop/extend forms; it
// reloads itself every 10 s. Drop leads to dropConfirmationPage first.
std::string adminPage(const nlohmann::json& status, const std::string& adminToken);
std::string dropConfirmationPage(const std::string& participant, const std::string& adminToken);
// "45 s", "3 min 05 s", "1 h 02 min" ("" for null).
std::string durationCell(const nlohmann::json& seconds);

}  // namespace tlab::study
