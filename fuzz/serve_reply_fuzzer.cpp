// Fuzz target: arbitrary bytes as the JSON body of a reply to a screen of `tlab serve` — a trial
// of every answer kind, a form with every field kind, consent, a message — checked by the screen
// and delivered through the participant's SessionChannel as POST /api/<token>/reply does. A reply
// must never crash the server: it is refused with a message (which the server sends as JSON) or
// delivered in the shape the session flow reads (BrowserResponder).
// fuzz-sources: study/serve/request_checks.cpp study/serve/session_channel.cpp study/serve/flow_pages.cpp study/serve/trial_page.cpp
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/serve_screens.hpp"
#include "study/serve/request_checks.hpp"
#include "study/serve/session_channel.hpp"

namespace {

using nlohmann::json;

void require(bool ok) {
  if (!ok) std::abort();
}

// What BrowserResponder reads of a delivered reply; any exception here would end a session.
void readAsTheFlowDoes(const tlab::study::Reply& r) {
  if (r.type == "answer") {
    require(!r.value["text"].get<std::string>().empty());
    require(r.value["rt_ms"].get<double>() >= 0.0);
  } else if (r.type == "onset") {
    r.value["painted_ms"].get<double>();
  } else if (r.type == "view") {
    r.value["view"].get<std::string>();
  } else if (r.type == "form") {
    r.value.get<std::vector<std::string>>();
  } else if (r.type == "consent") {
    r.value.get<bool>();
  } else {
    require(r.type == "continue" || r.type == "timeout");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const auto& screens = tlab::fuzz::serveScreens().screens;
  const tlab::study::Screen& screen = screens[data[0] % screens.size()];
  const json body = json::parse(std::string(reinterpret_cast<const char*>(data + 1), size - 1), nullptr, false);
  if (body.is_discarded() || !body.is_object()) return 0;  // the server refuses it before any screen sees it

  tlab::study::SessionChannel channel(std::chrono::minutes(5));
  const int seq = channel.publish(screen);
  std::string error;
  const auto delivery = channel.deliver(seq, body, 1, error);
  if (delivery == tlab::study::SessionChannel::Delivery::Refused) {
    require(!error.empty());
    tlab::study::jsonText({{"error", error}});  // the 400 body
    const auto refusals = channel.takeRefusals();
    require(refusals.size() == 1 && !json::parse(refusals[0].second).is_discarded());  // the stored refused-reply event
  } else {
    require(delivery == tlab::study::SessionChannel::Delivery::Delivered);
    const auto reply = channel.awaitReply(std::chrono::steady_clock::now());
    require(reply.has_value());
    readAsTheFlowDoes(*reply);
  }
  return 0;
}
