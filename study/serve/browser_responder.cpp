#include "study/serve/browser_responder.hpp"

#include <chrono>
#include <cstdio>

#include "study/run/session_wording.hpp"
#include "study/serve/flow_pages.hpp"

namespace tlab::study {

namespace {

SteadyTime steadyAt(std::int64_t ns) { return SteadyTime(std::chrono::duration_cast<SteadyTime::duration>(std::chrono::nanoseconds(ns))); }

}  // namespace

BrowserResponder::BrowserResponder(std::shared_ptr<SessionChannel> channel, ImagesFor images, DisplayInfo display,
                                   std::vector<ResponderEvent> arrival)
    : channel_(std::move(channel)), images_(std::move(images)), display_(std::move(display)), events_(std::move(arrival)) {}

void BrowserResponder::event(std::int64_t tNs, std::string kind, std::string detail) { events_.push_back({tNs, std::move(kind), std::move(detail)}); }

std::vector<ResponderEvent> BrowserResponder::takeEvents() {
  for (auto& [tNs, detail] : channel_->takeRefusals()) event(tNs, "refused-reply", std::move(detail));
  for (auto& e : channel_->takeEvents()) event(e.tNs, std::move(e.kind), std::move(e.detail));
  return std::exchange(events_, {});
}

std::optional<Reply> BrowserResponder::show(Screen screen) {
  channel_->publish(std::move(screen));
  auto reply = channel_->awaitReply(std::nullopt);
  channel_->publish(waitScreen());  // replies to the screen just answered are refused from now on
  return reply;
}

bool BrowserResponder::showMessage(const std::string& title, const std::string& text) { return show(messageScreen(title, text)).has_value(); }

std::optional<bool> BrowserResponder::askConsent(const std::string& title, const ConsentSpec& consent) {
  const auto reply = show(consentScreen(title, consent));
  if (!reply) return std::nullopt;
  if (reply->value.get<bool>() && !calibrate()) return std::nullopt;  // after consent: what it is for has been said
  return reply->value.get<bool>();
}

std::optional<std::vector<std::string>> BrowserResponder::fillForm(const std::string& title, const std::vector<FormField>& fields) {
  const auto reply = show(formScreen(title, fields, texts()));
  if (!reply) return std::nullopt;
  return reply->value.get<std::vector<std::string>>();
}

bool BrowserResponder::calibrate() {
  if (!askCalibration_ || calibration_) return true;
  const auto reply = show(calibrationScreen(noCard_));
  if (!reply) return false;
  calibration_ = reply->value;
  event(reply->receivedNs, "calibration", reply->value.dump());
  return true;
}

std::optional<Response> BrowserResponder::respond(const TrialView& view) {
  if (!calibrate()) return std::nullopt;
  Screen screen = trialScreen(view, images_(view));
  screen.page["question"] = questionWording(view.prepared.question, texts());  // in the participant's language
  if (calibration_) screen.page["px_per_cm"] = (*calibration_)["px_per_cm"];  // null: skipped
  channel_->publish(std::move(screen));
  Response response;
  std::optional<SteadyTime> deadline;
  for (;;) {
    auto reply = channel_->awaitReply(deadline);
    if (!reply) {
      channel_->publish(waitScreen());
      if (channel_->closed()) return std::nullopt;
      response.responseNs = monotonicNs();
      response.note = "no answer from the page within the time limit";
      return response;
    }
    if (reply->type == "view") {
      event(reply->receivedNs, "camera", reply->value["view"].get<std::string>());
      continue;
    }
    if (reply->type == "onset" || response.onsetNs == 0) {  // an answer without an onset report: shown at least by then
      const bool reported = reply->type == "onset";
      nlohmann::json detail{{"via", "browser"}, {"painted_ms", reported ? reply->value["painted_ms"] : nlohmann::json()}, {"reported", reported}};
      if (reported && !reply->value["shown"].is_null()) detail["shown"] = reply->value["shown"];  // the stimulus's size on the screen
      view.onset(reply->receivedNs, detail.dump());
      if (response.onsetNs == 0) {
        response.onsetNs = reply->receivedNs;
        deadline = steadyAt(reply->receivedNs) + std::chrono::duration_cast<SteadyTime::duration>(
                                                     std::chrono::duration<double>(view.limitSeconds + kNetworkGraceSeconds));
      }
      if (reported) continue;
    }
    channel_->publish(waitScreen());
    response.responseNs = reply->receivedNs;
    if (reply->type == "timeout") {
      response.note = "time limit reached in the browser";
      return response;
    }
    response.text = reply->value["text"].get<std::string>();
    response.rtSeconds = reply->value["rt_ms"].get<double>() / 1000.0;
    if (*response.rtSeconds > view.limitSeconds) {  // kept with its text, scored as missing by the runner
      char late[96];
      std::snprintf(late, sizeof late, "late: answered %.3f s after the time limit", *response.rtSeconds - view.limitSeconds);
      response.note = late;
    }
    // Both ends of the browser's RT, on the page's clock (performance.now()), kept as an event.
    nlohmann::json times{{"rt_ms", reply->value["rt_ms"]}};
    for (const char* key : {"painted_ms", "input_ms"})
      if (reply->value.contains(key)) times[key] = reply->value[key];
    event(reply->receivedNs, "answer-times", times.dump());
    return response;
  }
}

bool BrowserResponder::showFeedback(const TrialView& view, const Feedback& feedback) { return show(feedbackScreen(view, feedback)).has_value(); }

void BrowserResponder::showDebrief(const std::string& title, const DebriefSpec& debrief) {
  channel_->publish(endScreen(title, debrief.text, debrief.completionCode, completionUrl_));
}

bool BrowserResponder::takeBreak(const BreakSpec& spec) {
  const auto earliest = std::chrono::steady_clock::now() + std::chrono::duration_cast<SteadyTime::duration>(std::chrono::duration<double>(spec.minSeconds));
  channel_->publish(breakScreen(spec));
  for (;;) {
    if (!channel_->awaitReply(std::nullopt)) return false;
    if (std::chrono::steady_clock::now() + std::chrono::milliseconds(250) >= earliest) break;  // the page counts down too; an early press is ignored
  }
  channel_->publish(waitScreen());
  return true;
}

}  // namespace tlab::study
