#include "study/serve/participant_session.hpp"

#include <cstdio>
#include <random>

#include "study/run/trial_runner.hpp"
#include "study/serve/browser_responder.hpp"
#include "study/serve/flow_pages.hpp"

namespace tlab::study {

std::string newToken() {
  std::random_device device;  // /dev/urandom on Linux
  std::string token;
  for (int i = 0; i < 8; ++i) {
    char part[9];
    std::snprintf(part, sizeof part, "%08x", unsigned(device()));
    token += part;
  }
  return token;
}

ParticipantSession::ParticipantSession(std::string participant, std::string token, nlohmann::json arrival, std::chrono::milliseconds timeout)
    : participant_(std::move(participant)), token_(std::move(token)), arrival_(std::move(arrival)), timeout_(timeout),
      channel_(std::make_shared<SessionChannel>(timeout)) {}

ParticipantSession::~ParticipantSession() {
  stop();
  std::thread walking;
  {
    std::lock_guard lock(mutex_);
    walking = std::move(thread_);
  }
  if (walking.joinable()) walking.join();
}

void ParticipantSession::start(ServedStudy& study, const nlohmann::json& browser) {
  std::lock_guard lock(mutex_);
  if (running_) return;
  // A session that ended (finished, declined, dropped) keeps its end screen: a reload of the page
  // shows it again. One stopped by an error ("Try again"), or timed out before the participant was
  // enrolled (nothing stored), starts again.
  if (!ended_.empty() && !restartable_) return;
  restartable_ = false;
  if (thread_.joinable()) thread_.join();
  if (channel_->closed()) {  // a fresh start after an error; events not stored yet (a takeover) go with it
    auto events = channel_->takeEvents();
    channel_ = std::make_shared<SessionChannel>(timeout_);
    for (auto& event : events) channel_->note(std::move(event));
  }
  ended_.clear();
  DisplayInfo display;
  const gpu::GpuInfo& gl = study.worker.gpuInfo();
  display.glBackend = gl.backend;  // the headless context that rendered the stimuli
  display.glVendor = gl.vendor;
  display.glRenderer = gl.renderer;
  display.glVersion = gl.version;
  display.browserJson = browser.dump();
  std::vector<ResponderEvent> arrival{{monotonicNs(), "arrival", arrival_.dump()}};
  running_ = true;
  startedAt_ = std::chrono::steady_clock::now();
  endedAt_.reset();
  thread_ = std::thread([this, &study, display, arrival] { walk(study, display, arrival); });
}

void ParticipantSession::endWith(const std::string& title, const std::string& text, const std::string& code, const std::string& url) {
  channel()->publish(endScreen(title, text, code, url));
  std::lock_guard lock(mutex_);
  ended_ = text;
}

void ParticipantSession::walk(ServedStudy& study, DisplayInfo display, std::vector<ResponderEvent> arrival) {
  const Experiment& e = study.experiment;
  const ParticipantTexts& t = e.texts;
  const std::string title = e.participantTitle.empty() ? t.text("title.page") : e.participantTitle;
  try {
    const auto existing = study.store.findParticipant(e.id, participant_);
    const RunOptions options{participant_, existing.has_value(), study.tlabVersion};
    BrowserResponder responder(
        channel_, [&](const TrialView& view) { return study.worker.images(view.plan, view.prepared); }, display, std::move(arrival));
    responder.completionUrl(e.online.completionUrl);
    responder.askCalibration(e.online.sizeCalibration, e.online.calibrationNoCard);
    if (existing && e.online.sizeCalibration)  // calibrated in an earlier session (before a server restart, too)
      if (const auto earlier = study.store.lastEventDetail(existing->id, "calibration")) {
        auto calibration = nlohmann::json::parse(*earlier, nullptr, false);
        if (calibration.is_object() && calibration.contains("px_per_cm")) responder.knownCalibration(std::move(calibration));
      }
    TrialRunner runner(e, study.store, study.worker);
    const SessionResult r = runner.run(options, responder);
    if (r.outcome == SessionOutcome::Finished) {
      std::lock_guard lock(mutex_);  // the responder showed the debrief page, which stays
      ended_ = "finished";
    } else if (r.outcome == SessionOutcome::Declined) {
      {
        std::lock_guard lock(mutex_);  // declined before the page shows its end: the admin page never lists it as running
        ended_ = "declined";
      }
      channel()->publish(endScreen(title, t.text("flow.declined_close"), "", ""));
    } else if (channel_->timedOut() && study.store.findParticipant(e.id, participant_)) {  // enrolled: the slot is freed
      study.store.dropParticipant(e.id, participant_, channel_->closedBecause());
      endWith(title, t.text("end.timed_out_replaced"));
    } else if (channel_->timedOut()) {  // still at the welcome or the consent: nothing was stored, they may start again
      endWith(title, t.text("end.timed_out_restart"));
      std::lock_guard lock(mutex_);
      restartable_ = true;
    } else if (channel_->closed()) {
      endWith(title, t.text("end.closed"));
    }
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "serve: participant '%s': %s\n", participant_.c_str(), ex.what());
    Screen s;
    s.page = {{"kind", "error"},
              {"text", t.text("end.server_problem")},
              {"retry", true}};
    channel_->publish(std::move(s));
    channel_->close("the server could not continue the session");  // the details go to the log, not to the page
    std::lock_guard lock(mutex_);
    ended_ = std::string("error: ") + ex.what();
    restartable_ = true;
  }
  std::lock_guard lock(mutex_);
  endedAt_ = std::chrono::steady_clock::now();
  running_ = false;
}

std::shared_ptr<SessionChannel> ParticipantSession::channel() const {
  std::lock_guard lock(mutex_);
  return channel_;
}

void ParticipantSession::drop(ServedStudy& study, const std::string& reason) {
  channel()->close(reason);
  std::thread walking;
  {
    std::lock_guard lock(mutex_);
    walking = std::move(thread_);
  }
  if (walking.joinable()) walking.join();  // outside the lock: the walk takes it to say how it ended
  study.store.dropParticipant(study.experiment.id, participant_, reason);
}

void ParticipantSession::stop() { channel()->close("the server is shutting down"); }

bool ParticipantSession::admit(const std::string& browser) {
  std::lock_guard lock(mutex_);
  if (browser == browser_) return true;
  if (browser_.empty()) {
    browser_ = browser;
    return true;
  }
  if (!channel_->silent()) return false;
  std::fprintf(stderr, "serve: participant '%s': session taken over by another browser after the time-out of silence\n", participant_.c_str());
  channel_->note({monotonicNs(), "takeover", nlohmann::json{{"from", browser_.substr(0, 8)}, {"to", browser.substr(0, 8)}}.dump()});
  browser_ = browser;
  return true;
}

void ParticipantSession::release() {
  std::lock_guard lock(mutex_);
  if (!running_ && !startedAt_) browser_.clear();
}

std::optional<double> ParticipantSession::elapsedSeconds() const {
  std::lock_guard lock(mutex_);
  if (!startedAt_) return std::nullopt;
  const auto until = running_ || !endedAt_ ? std::chrono::steady_clock::now() : *endedAt_;  // an ended session's time stops
  return std::chrono::duration<double>(until - *startedAt_).count();
}

std::string ParticipantSession::state() const {
  std::lock_guard lock(mutex_);
  if (ended_ == "declined") return ended_;  // set before its end screen is published, while the walk still winds up
  if (running_) return channel_->idleSeconds() > kIdleSeconds ? "idle" : "running";
  if (!ended_.empty()) return "ended: " + ended_;
  return "waiting for the page";
}

}  // namespace tlab::study
