#pragma once
// SessionChannel: the meeting point of one participant's session thread (which walks the session
// flow through a BrowserResponder) and the HTTP threads serving that participant's page. The
// session thread publishes a Screen and waits for replies; an HTTP thread checks a reply against
// the screen on show (Screen::check: wrong kinds are refused with a message, never delivered) and
// hands it over. Screens are numbered, so a reply to a screen that is gone (a second tab, a reply
// resent after a reload) is told so rather than taken for an answer to another.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace tlab::study {

struct LiveTrial;  // study/serve/live_frames.hpp

using SteadyTime = std::chrono::steady_clock::time_point;

// A reply the page sent, after its check: `type` ("answer", "onset", "view", ...) and its value.
struct Reply {
  std::string type;
  nlohmann::json value;
  std::int64_t receivedNs = 0;  // monotonic clock when the request arrived
};

// What the check of a reply says: an error (the request is refused with 400) or the reply.
// A refused answer also says why in the participant's words: `refusal` is {"key": a text-table
// key, "args": {name: value}} (the page formats it with its table), or null.
struct Checked {
  Checked(std::string e = "", Reply r = {}, nlohmann::json why = nullptr) : error(std::move(e)), reply(std::move(r)), refusal(std::move(why)) {}
  std::string error;
  Reply reply;
  nlohmann::json refusal;
};

struct Screen {
  nlohmann::json page;  // what the page shows (never a ground truth)
  std::function<Checked(const nlohmann::json&)> check;
  std::set<std::string> images;  // SHA-256 names this screen may fetch
  std::shared_ptr<const LiveTrial> live;  // a live trial: the scene, style and start its frames come from
};

class SessionChannel {
 public:
  explicit SessionChannel(std::chrono::milliseconds timeout) : timeout_(timeout), lastActivity_(std::chrono::steady_clock::now()) {}

  // Session thread: shows `screen` (numbered from 1) and returns its number.
  int publish(Screen screen);
  // Session thread: the next reply to the current screen; nullopt when the channel was closed
  // or nothing arrived from the page before `deadline` or for the inactivity time-out.
  std::optional<Reply> awaitReply(std::optional<SteadyTime> deadline);

  // HTTP threads.
  nlohmann::json current() const;  // the page of the current screen, with "seq"
  // Checks and delivers a reply to screen `seq`. Stale: the screen is gone or the session ended
  // (the page should show the current one); Refused: the check's error is in `error`.
  enum class Delivery { Delivered, Stale, Refused };
  // `refusal`: the check's participant-facing reason, when it gave one.
  Delivery deliver(int seq, const nlohmann::json& body, std::int64_t receivedNs, std::string& error, nlohmann::json* refusal = nullptr);
  // Waits up to `wait` until the session thread has handled every reply delivered so far (an
  // onset is then committed): the acknowledgement of replies that do not change the screen.
  bool awaitHandled(std::chrono::milliseconds wait);
  // Waits up to `wait` for a screen after `seq`; returns the current page either way.
  nlohmann::json awaitScreenAfter(int seq, std::chrono::milliseconds wait);
  bool mayFetch(const std::string& sha) const;
  // The live trial of screen `seq` while it is on show (nullptr: another screen, not live, ended).
  std::shared_ptr<const LiveTrial> liveTrial(int seq) const;
  // Keeps a live frame's "frame" event when `trial` is still the one on show as screen `seq` (the
  // frame may then be sent: every frame sent is logged); false otherwise. The session thread stores
  // the frames with the trial (takeEvents).
  bool noteFrame(int seq, const std::shared_ptr<const LiveTrial>& trial, std::int64_t tNs, std::string detail);
  static constexpr std::size_t kMaxFramesPerTrial = 200000;
  // Refused replies are kept as events ("refused-reply") until the session thread stores them.
  std::vector<std::pair<std::int64_t, std::string>> takeRefusals();
  // Answers to a screen that had gone ("late-answer") and what the server noted of the session
  // ("takeover"): events kept until the session thread stores them.
  struct Event {
    std::int64_t tNs = 0;
    std::string kind, detail;
  };
  void note(Event event);
  std::vector<Event> takeEvents();
  // No request from the page for the inactivity time-out.
  bool silent() const;
  // Seconds since the page's last request.
  double idleSeconds() const;
  int refusals() const;
  void touch();

  // Ends the session's waiting (the researcher dropped the participant; the server stops).
  void close(const std::string& why);
  bool closed() const;
  std::string closedBecause() const;
  bool timedOut() const;
  void extend(std::chrono::milliseconds more);

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::chrono::milliseconds timeout_;
  SteadyTime lastActivity_;
  int seq_ = 0;
  Screen screen_;
  std::deque<Reply> replies_;
  std::int64_t delivered_ = 0, handled_ = 0, popped_ = 0;  // replies counted
  std::set<std::string> images_;
  std::vector<std::pair<std::int64_t, std::string>> refused_;
  std::vector<Event> events_;
  std::vector<Event> frames_;
  int refusals_ = 0;
  std::string closedBecause_;
  bool timedOut_ = false;
};

}  // namespace tlab::study
