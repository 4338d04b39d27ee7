#include "study/serve/session_channel.hpp"

#include <cstdio>

#include "study/serve/request_checks.hpp"

namespace tlab::study {

int SessionChannel::publish(Screen screen) {
  std::lock_guard lock(mutex_);
  screen_ = std::move(screen);
  images_.insert(screen_.images.begin(), screen_.images.end());
  popped_ += std::int64_t(replies_.size());  // replies to the old screen are dropped: nothing more to handle
  handled_ = popped_;
  replies_.clear();
  ++seq_;
  changed_.notify_all();
  return seq_;
}

std::optional<Reply> SessionChannel::awaitReply(std::optional<SteadyTime> deadline) {
  std::unique_lock lock(mutex_);
  handled_ = popped_;  // the thread is back for more: what it took before is handled
  changed_.notify_all();
  for (;;) {
    if (!closedBecause_.empty()) return std::nullopt;
    if (!replies_.empty()) {
      Reply r = std::move(replies_.front());
      replies_.pop_front();
      ++popped_;
      return r;
    }
    const SteadyTime idle = lastActivity_ + timeout_;
    const SteadyTime until = deadline ? std::min(*deadline, idle) : idle;
    if (std::chrono::steady_clock::now() >= until) {
      if (deadline && *deadline <= idle) return std::nullopt;
      timedOut_ = true;
      char minutes[32];
      std::snprintf(minutes, sizeof minutes, "%g", double(timeout_.count()) / 60000.0);
      closedBecause_ = std::string("timed out after ") + minutes + " minutes without a request from the page";
      return std::nullopt;
    }
    changed_.wait_until(lock, until);
  }
}

nlohmann::json SessionChannel::current() const {
  std::lock_guard lock(mutex_);
  nlohmann::json page = screen_.page.is_null() ? nlohmann::json{{"kind", "wait"}} : screen_.page;
  page["seq"] = seq_;
  return page;
}

SessionChannel::Delivery SessionChannel::deliver(int seq, const nlohmann::json& body, std::int64_t receivedNs, std::string& error,
                                                nlohmann::json* refusal) {
  std::lock_guard lock(mutex_);
  lastActivity_ = std::chrono::steady_clock::now();
  if (!closedBecause_.empty()) {
    error = "the session has ended: " + closedBecause_;
    return Delivery::Stale;
  }
  if (seq != seq_ || !screen_.check) {
    error = "screen " + std::to_string(seq) + " is no longer shown; the current one is " + std::to_string(seq_);
    // An answer to a trial that has gone (its time ran out on the server first): kept as an event.
    // (type compared as JSON: a stale reply whose type is no text is no answer, and no exception)
    if (body.is_object() && body.contains("type") && body.at("type") == "answer" && events_.size() < 100)
      events_.push_back({receivedNs, "late-answer", jsonText({{"screen", seq}, {"current", seq_}, {"body", body.dump().substr(0, 500)}})});
    return Delivery::Stale;
  }
  Checked c;
  try {
    c = screen_.check(body);
  } catch (const std::exception& e) {  // a check that met a JSON type it did not expect ({"type": true}): still a refusal
    c.error = std::string("reply: ") + e.what();
  }
  if (!c.error.empty()) {
    ++refusals_;
    // jsonText: the body cut at 500 bytes may end inside a character.
    if (refused_.size() < 100) refused_.emplace_back(receivedNs, jsonText({{"error", c.error}, {"body", body.dump().substr(0, 500)}}));
    error = c.error;
    if (refusal) *refusal = c.refusal;
    return Delivery::Refused;
  }
  c.reply.receivedNs = receivedNs;
  replies_.push_back(std::move(c.reply));
  ++delivered_;
  changed_.notify_all();
  return Delivery::Delivered;
}

nlohmann::json SessionChannel::awaitScreenAfter(int seq, std::chrono::milliseconds wait) {
  {
    std::unique_lock lock(mutex_);
    // A "wait" screen is the gap between two screens (the runner storing an answer): wait past it.
    changed_.wait_for(lock, wait, [&] { return (seq_ > seq && screen_.page.value("kind", "") != "wait") || !closedBecause_.empty(); });
  }
  return current();
}

bool SessionChannel::awaitHandled(std::chrono::milliseconds wait) {
  std::unique_lock lock(mutex_);
  const std::int64_t upTo = delivered_;
  return changed_.wait_for(lock, wait, [&] { return handled_ >= upTo || !closedBecause_.empty(); });
}

bool SessionChannel::mayFetch(const std::string& sha) const {
  std::lock_guard lock(mutex_);
  return images_.count(sha) > 0;
}

std::shared_ptr<const LiveTrial> SessionChannel::liveTrial(int seq) const {
  std::lock_guard lock(mutex_);
  if (seq != seq_ || !closedBecause_.empty()) return nullptr;
  return screen_.live;
}

bool SessionChannel::noteFrame(int seq, const std::shared_ptr<const LiveTrial>& trial, std::int64_t tNs, std::string detail) {
  std::lock_guard lock(mutex_);
  if (seq != seq_ || !closedBecause_.empty() || !trial || screen_.live != trial || frames_.size() >= kMaxFramesPerTrial) return false;
  frames_.push_back({tNs, "frame", std::move(detail)});
  lastActivity_ = std::chrono::steady_clock::now();
  return true;
}

std::vector<std::pair<std::int64_t, std::string>> SessionChannel::takeRefusals() {
  std::lock_guard lock(mutex_);
  return std::exchange(refused_, {});
}

void SessionChannel::note(Event event) {
  std::lock_guard lock(mutex_);
  if (events_.size() < 100) events_.push_back(std::move(event));
}

std::vector<SessionChannel::Event> SessionChannel::takeEvents() {
  std::lock_guard lock(mutex_);
  std::vector<Event> taken = std::exchange(events_, {});
  taken.insert(taken.end(), std::make_move_iterator(frames_.begin()), std::make_move_iterator(frames_.end()));
  frames_.clear();
  return taken;
}

double SessionChannel::idleSeconds() const {
  std::lock_guard lock(mutex_);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - lastActivity_).count();
}

bool SessionChannel::silent() const {
  std::lock_guard lock(mutex_);
  return std::chrono::steady_clock::now() >= lastActivity_ + timeout_;
}

int SessionChannel::refusals() const {
  std::lock_guard lock(mutex_);
  return refusals_;
}

void SessionChannel::touch() {
  std::lock_guard lock(mutex_);
  lastActivity_ = std::chrono::steady_clock::now();
}

void SessionChannel::close(const std::string& why) {
  std::lock_guard lock(mutex_);
  if (closedBecause_.empty()) closedBecause_ = why;
  changed_.notify_all();
}

bool SessionChannel::closed() const {
  std::lock_guard lock(mutex_);
  return !closedBecause_.empty();
}

std::string SessionChannel::closedBecause() const {
  std::lock_guard lock(mutex_);
  return closedBecause_;
}

bool SessionChannel::timedOut() const {
  std::lock_guard lock(mutex_);
  return timedOut_;
}

void SessionChannel::extend(std::chrono::milliseconds more) {
  std::lock_guard lock(mutex_);
  timeout_ += more;
  changed_.notify_all();
}

}  // namespace tlab::study
