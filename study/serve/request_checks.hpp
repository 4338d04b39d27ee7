#pragma once
// The checks of what a request of `tlab serve` brings before anything acts on it: the participant
// id from the link, and the page's display report. Apart from the server (study_server.cpp) so
// the serve_request fuzz target reaches them without a socket.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace tlab::study {

// 1 to 128 letters, digits or _.@- (Prolific ids and the like; nothing a path or a log could misread).
bool validParticipantId(const std::string& id);

// The browser key of a request: the value of its tlab-browser cookie when that is 32 hex digits
// (the participant page makes one per browser), "" otherwise.
std::string browserKey(const std::string& cookieHeader);

// The page's display report: only numbers, booleans and short texts, at most 40 keys; the
// reason when it is anything else.
std::optional<std::string> checkDisplay(const nlohmann::json& body);

// A text taken from a request (a header, a link parameter), cut to about `maxBytes`: a request
// may carry any bytes, and JSON text must be UTF-8 (nlohmann's dump() throws on anything else),
// so invalid sequences, a character cut in two included, become U+FFFD.
std::string requestText(const std::string& raw, std::size_t maxBytes);

// What is stored of an arrival: the participant id, the browser's User-Agent and the link's
// study and session parameters (name, value).
nlohmann::json arrivalRecord(const std::string& participant, const std::string& userAgent,
                             const std::vector<std::pair<std::string, std::string>>& linkParameters);

// The JSON text the server sends or stores: never throws, even when an error message quotes a
// request's text cut inside a character.
std::string jsonText(const nlohmann::json& value);

}  // namespace tlab::study
