#pragma once
// BrowserResponder: the participant's browser as a front end of the one session flow
// (TrialRunner). Each Responder call publishes a screen on the participant's SessionChannel and
// waits for the page's reply; the HTTP threads check replies before they arrive here. Onsets are
// the page's report that the stimulus was painted (requestAnimationFrame after decode): the runner
// commits each at once. RT is the browser's, from that paint to the input event; the server's
// monotonic clock gives onset and response times as they arrived. A trial's time limit runs on the
// server from the first onset (plus a grace for the network), so a page that goes quiet cannot
// hold a trial open.
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "study/run/responder.hpp"
#include "study/serve/session_channel.hpp"
#include "study/serve/trial_page.hpp"

namespace tlab::study {

class BrowserResponder : public Responder {
 public:
  using ImagesFor = std::function<TrialImages(const TrialView&)>;
  // `arrival`: events stored with the session's first events (the URL parameters, the display).
  BrowserResponder(std::shared_ptr<SessionChannel> channel, ImagesFor images, DisplayInfo display, std::vector<ResponderEvent> arrival);

  std::string mode() const override { return "browser"; }
  bool showMessage(const std::string& title, const std::string& text) override;
  std::optional<bool> askConsent(const std::string& title, const ConsentSpec& consent) override;
  std::optional<std::vector<std::string>> fillForm(const std::string& title, const std::vector<FormField>& fields) override;
  std::optional<Response> respond(const TrialView& view) override;
  bool showFeedback(const TrialView& view, const Feedback& feedback) override;
  bool takeBreak(const BreakSpec& spec) override;
  // The end page: the debrief, the completion code and the link back to the platform; it stays.
  void showDebrief(const std::string& title, const DebriefSpec& debrief) override;
  void completionUrl(std::string url) { completionUrl_ = std::move(url); }
  // [online] size_calibration: the credit-card screen right after consent (or before the first
  // trial of a returning participant); `noCard` offers "I have no card".
  void askCalibration(bool ask, bool noCard) { askCalibration_ = ask, noCard_ = noCard; }
  // The calibration this participant gave in an earlier session (its stored event's detail): not
  // asked again, and every trial page carries its px_per_cm.
  void knownCalibration(nlohmann::json calibration) { calibration_ = std::move(calibration); }
  std::vector<ResponderEvent> takeEvents() override;
  std::optional<DisplayInfo> display() const override { return display_; }

  static constexpr double kNetworkGraceSeconds = 10.0;

 private:
  std::optional<Reply> show(Screen screen);
  // Shows the calibration once per participant's session; false: the session was closed.
  bool calibrate();
  void event(std::int64_t tNs, std::string kind, std::string detail);

  std::shared_ptr<SessionChannel> channel_;
  ImagesFor images_;
  DisplayInfo display_;
  std::vector<ResponderEvent> events_;
  std::string completionUrl_;
  bool askCalibration_ = false, noCard_ = false;
  std::optional<nlohmann::json> calibration_;  // the participant's calibration (server side: every trial page carries px_per_cm)
};

}  // namespace tlab::study
