// Fuzz target: what a request brings to `tlab serve`, without a socket (a StudyServer needs a GL
// render worker and a store per run): the first byte picks the route, the rest is its data —
//   0: the participants' link's query (/s/ID?...): the participant id check and the arrival record
//      with the same bytes as User-Agent and link parameters, stored as JSON text;
//   1: the body of POST /api/<token>/display: the display report check, and the report as stored;
//   2..: the body of POST /api/<token>/reply: the 'seq' check, then SessionChannel::deliver to one
//      of the screens of fuzz/serve_screens.hpp, and the JSON the server answers with.
// No input may crash or throw; every refusal is a message.
// fuzz-sources: study/serve/request_checks.cpp study/serve/session_channel.cpp study/serve/flow_pages.cpp study/serve/trial_page.cpp
#include <httplib.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/serve_screens.hpp"
#include "study/serve/request_checks.hpp"

namespace {

using nlohmann::json;
using namespace tlab::study;

void arrival(const std::string& query) {
  httplib::Params params;
  httplib::detail::parse_query_text(query, params);
  std::vector<std::pair<std::string, std::string>> link;  // the parameters the experiment names (Prolific's here)
  for (const auto& [name, value] : params)
    if (name == "STUDY_ID" || name == "SESSION_ID") link.emplace_back(name, value);
  const auto pid = params.find("pid");
  const std::string id = pid == params.end() ? "" : pid->second;
  if (!validParticipantId(id)) return;
  jsonText(arrivalRecord(id, query, link));
  if (arrivalRecord(id, query, link).dump().empty()) std::abort();  // stored with dump(): must be valid UTF-8
}

void display(const json& body) {
  if (!body.is_object()) return;
  if (const auto error = checkDisplay(body)) {
    if (error->empty()) std::abort();
    jsonText({{"error", "display: " + *error}});
    return;
  }
  body.dump();  // stored as the session's browser JSON
}

void reply(const Screen& screen, const json& body) {
  if (!body.is_object()) return;
  const auto seq = body.find("seq");
  if (seq == body.end() || !seq->is_number_integer()) return;
  SessionChannel channel(std::chrono::minutes(5));
  channel.publish(screen);
  std::string error;
  const auto delivery = channel.deliver(seq->get<int>(), body, 1, error);
  if (delivery != SessionChannel::Delivery::Delivered && error.empty()) std::abort();
  jsonText(delivery == SessionChannel::Delivery::Stale ? json{{"error", error}, {"screen", channel.current()}} : json{{"error", error}});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string rest(reinterpret_cast<const char*>(data + 1), size - 1);
  if (data[0] == 0) return arrival(rest), 0;
  const json body = json::parse(rest, nullptr, false);
  if (body.is_discarded()) return 0;  // refused: "the body is not a JSON object"
  if (data[0] == 1) return display(body), 0;
  const auto& screens = tlab::fuzz::serveScreens().screens;
  reply(screens[data[0] % screens.size()], body);
  return 0;
}
