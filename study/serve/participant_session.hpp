#pragma once
// ParticipantSession: one participant of a served study — their unguessable token, the channel
// their page talks through, and the thread that walks the session flow (TrialRunner with a
// BrowserResponder) against the shared Store. The thread starts when the page has reported its
// display; after a storage error or a server restart the next visit starts it again and the flow
// resumes at the first unanswered trial, as `tlab run --resume` does.
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "study/design/experiment.hpp"
#include "study/serve/render_worker.hpp"
#include "study/serve/session_channel.hpp"
#include "study/store/store.hpp"

namespace tlab::study {

// What every session of one server shares.
struct ServedStudy {
  const Experiment& experiment;
  Store& store;
  RenderWorker& worker;
  std::string tlabVersion;
};

class ParticipantSession {
 public:
  ParticipantSession(std::string participant, std::string token, nlohmann::json arrival, std::chrono::milliseconds timeout);
  ~ParticipantSession();
  ParticipantSession(const ParticipantSession&) = delete;
  ParticipantSession& operator=(const ParticipantSession&) = delete;

  const std::string& participant() const { return participant_; }
  const std::string& token() const { return token_; }
  std::shared_ptr<SessionChannel> channel() const;

  // Starts the session thread with the page's display report, unless it runs already.
  void start(ServedStudy& study, const nlohmann::json& browser);
  bool running() const { return running_; }
  // The researcher drops the participant: the flow stops and the slot is freed.
  void drop(ServedStudy& study, const std::string& reason);
  // Stops waiting for the page (the server shuts down); the session is left to resume.
  void stop();
  // "waiting for the page", "running", "idle" (running, but no request from the page for
  // kIdleSeconds: its browser is likely closed), "declined", "ended: ...".
  std::string state() const;
  static constexpr double kIdleSeconds = 45.0;  // an open page asks for its screen every 30 s
  // Seconds since the session thread started (nullopt: not started in this server's run).
  std::optional<double> elapsedSeconds() const;
  // Whether a request from the browser with this key (its tlab-browser cookie; "" when none) may
  // act on the session. The first browser that brings a key binds the session to it; another one
  // is let in only after the session's page has been silent for the time-out, and that takeover
  // is logged (stderr and a "takeover" event).
  bool admit(const std::string& browser);
  // Forgets the browser that opened a session that never started (a refused device), so that the
  // participant can come back at once in another browser.
  void release();

 private:
  void walk(ServedStudy& study, DisplayInfo display, std::vector<ResponderEvent> arrival);
  void endWith(const std::string& title, const std::string& text, const std::string& code = "", const std::string& url = "");

  std::string participant_, token_;
  nlohmann::json arrival_;
  std::chrono::milliseconds timeout_;
  std::shared_ptr<SessionChannel> channel_;
  std::atomic<bool> running_{false};
  mutable std::mutex mutex_;
  std::string ended_;
  std::optional<std::chrono::steady_clock::time_point> startedAt_, endedAt_;
  std::string browser_;        // the browser key the session is bound to ("": none yet)
  bool restartable_ = false;  // ended by an error, or timed out before enrolment: a new visit starts again
  std::thread thread_;
};

// 32 random bytes from the system's generator, as 64 hex digits.
std::string newToken();

}  // namespace tlab::study
