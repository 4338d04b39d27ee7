#include "study/serve/live_frames.hpp"

#include <algorithm>
#include <cmath>

#include "renderer/params/style_params.hpp"

namespace tlab::study {

namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

LiveAnswer superseded() { return LiveAnswer{}; }

}  // namespace

bool withinLiveBounds(const LiveTrial& trial, const render::Camera& camera) {
  if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up)) return false;
  const render::BoundingSphere sphere = trial.scene->boundingSphere();
  const float reach = 1.5f * std::max(sphere.radius, glm::length(trial.start.eye - sphere.center));
  return glm::length(camera.eye - sphere.center) <= reach;
}

void steer(CameraNavigator& navigator, const LiveTrial& trial, const ViewInput& input) {
  auto keepWithinBounds = [&](const CameraNavigator& before) {
    if (!withinLiveBounds(trial, navigator.camera())) navigator = before;
  };
  if (input.dx != 0.0 || input.dy != 0.0) {
    const CameraNavigator before = navigator;
    navigator.drag(input.dx, input.dy);
    keepWithinBounds(before);
  }
  if (input.forward != 0 || input.turn != 0) {
    const CameraNavigator before = navigator;
    navigator.move(input.forward, input.turn);
    keepWithinBounds(before);
  }
}

std::string liveViewKey(const LiveTrial& trial) {
  return trial.stimulus.text() + " | " + navigationName(trial.navigation) + " | " + render::cameraText(trial.start);
}

bool liveViewShareable(const LiveTrial& trial) { return trial.stimulus.style != "dynamic"; }

bool lensFollowsCursor(const StimulusKey& stimulus) {
  std::map<std::string, std::string> settings;
  for (const auto& s : stimulus.renderSettings) render::addSetting(settings, s);
  const auto mode = settings.find("mode");
  return stimulus.style == "dynamic" && mode != settings.end() && mode->second == "active";
}

std::future<LiveAnswer> LiveFrameQueue::submit(LiveRequest request) {
  const auto it = pending_.find(request.session);
  if (it == pending_.end()) {
    order_.push_back(request.session);
    Pending p{std::move(request), {}};
    auto future = p.answer.get_future();
    pending_.emplace(p.request.session, std::move(p));
    return future;
  }
  // Dropped, not queued: the waiting frame is answered "superseded"; its input (of the same trial)
  // is not lost but goes before the newer input. The session keeps its place in the turn.
  Pending& old = it->second;
  if (old.request.trial == request.trial) request.input = old.request.input.then(request.input);
  old.answer.set_value(superseded());
  old = Pending{std::move(request), {}};
  return old.answer.get_future();
}

std::optional<LiveFrameQueue::Taken> LiveFrameQueue::take(LiveClock::time_point now) {
  for (auto it = order_.begin(); it != order_.end(); ++it) {
    const auto last = started_.find(*it);
    if (last != started_.end() && last->second + interval_ > now) continue;  // this session's rate: not yet
    const auto p = pending_.find(*it);
    Taken taken{std::move(p->second.request), std::move(p->second.answer)};
    pending_.erase(p);
    started_[*it] = now;
    order_.erase(it);
    return taken;
  }
  return std::nullopt;
}

std::optional<LiveClock::time_point> LiveFrameQueue::nextDue() const {
  std::optional<LiveClock::time_point> due;
  for (const auto& session : order_) {
    const auto last = started_.find(session);
    const LiveClock::time_point at = last == started_.end() ? LiveClock::time_point::min() : last->second + interval_;
    if (!due || at < *due) due = at;
  }
  return due;
}

void LiveFrameQueue::clear() {
  for (auto& [session, p] : pending_) p.answer.set_value(superseded());
  pending_.clear();
  order_.clear();
}

}  // namespace tlab::study
