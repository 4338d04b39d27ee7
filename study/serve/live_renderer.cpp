#include "study/serve/live_renderer.hpp"

#include <chrono>
#include <cstdint>

#include "study/run/camera_navigator.hpp"
#include "study/serve/gl_thread.hpp"

namespace tlab::study {

namespace {

double msSince(LiveClock::time_point start) { return std::chrono::duration<double, std::milli>(LiveClock::now() - start).count(); }

std::unique_ptr<LiveView> newView(const LiveTrial& t) { return std::make_unique<LiveView>(t.scene, t.stimulus, t.navigation, t.start); }

}  // namespace

LiveRenderer::LiveRenderer(double framesPerSecond) : queue_(framesPerSecond) {
  thread_ = startGlThread([](const gpu::GpuContext&) {}, [this] { loop(); });
}

LiveRenderer::~LiveRenderer() { stopGlThread(mutex_, stopping_, wake_, thread_); }

void LiveRenderer::loop() {
  for (;;) {
    std::function<void()> job;
    std::optional<LiveFrameQueue::Taken> frame;
    {
      std::unique_lock lock(mutex_);
      for (;;) {  // a warm-up waited for first; then a live frame that is due; then other warm-ups; else wait
        if (!jobs_.empty() || stopping_) break;
        if ((frame = queue_.take(LiveClock::now()))) break;
        if (!idle_.empty()) break;
        if (const auto due = queue_.nextDue()) wake_.wait_until(lock, *due);
        else wake_.wait(lock);
      }
      if (!frame && jobs_.empty() && stopping_) break;
      auto& from = jobs_.empty() ? idle_ : jobs_;
      if (!frame) {
        job = std::move(from.front());
        from.pop_front();
      }
    }
    if (job) job();
    if (frame) {
      try {
        frame->answer.set_value(render(frame->request));
      } catch (...) {
        frame->answer.set_exception(std::current_exception());
      }
    }
  }
  {
    std::lock_guard lock(mutex_);
    queue_.clear();
  }
  slots_.clear();  // their renderers' GL objects go while the context is current
  sharedViews_.clear();
  spareViews_.clear();
}

LiveAnswer LiveRenderer::frame(LiveRequest request) {
  std::future<LiveAnswer> answer;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return LiveAnswer{};
    answer = queue_.submit(std::move(request));
  }
  wake_.notify_one();
  return answer.get();
}

std::future<void> LiveRenderer::warm(const LiveTrial& trial, bool urgent) {
  auto task = std::make_shared<std::packaged_task<void()>>([this, trial] { warmNow(trial); });
  auto done = task->get_future();
  {
    std::lock_guard lock(mutex_);
    auto& to = urgent ? jobs_ : idle_;
    if (!urgent && idle_.size() >= kLiveViews) return done;  // enough waiting; dropped (the future reports a broken promise)
    to.push_back([task] { (*task)(); });
  }
  wake_.notify_one();
  return done;
}

LiveRenderer::KeptView LiveRenderer::makeWarmView(const LiveTrial& trial) {
  KeptView k{newView(trial), nullptr, ++uses_};
  k.start = std::make_shared<const Canvas>(k.view->frameFrom(k.view->navigator().camera()));  // as a session's frame 0
  return k;
}

void LiveRenderer::warmNow(const LiveTrial& trial) {
  const std::string key = liveViewKey(trial);
  auto& kept = liveViewShareable(trial) ? sharedViews_ : spareViews_;
  const auto it = kept.find(key);
  if (it != kept.end() && it->second.start) return;
  std::size_t views = sharedViews_.size() + spareViews_.size();
  for (const auto& [session, slot] : slots_) views += slot.view ? 1 : 0;
  if (it == kept.end() && views >= kLiveViews) return;  // no room: made when a session asks
  if (it == kept.end()) kept.emplace(key, makeWarmView(trial));
  else it->second.start = std::make_shared<const Canvas>(it->second.view->frameFrom(it->second.view->navigator().camera()));
}

LiveView& LiveRenderer::sharedView(const LiveTrial& trial, std::uint64_t use) {
  KeptView& kept = sharedViews_[liveViewKey(trial)];
  if (!kept.view) kept.view = newView(trial);
  kept.used = use;
  return *kept.view;
}

// The least recently used views go while more than kLiveViews are kept (a session's own, a shared
// one, a spare).
void LiveRenderer::dropLeastRecentlyUsedViews() {
  for (;;) {
    std::size_t views = sharedViews_.size() + spareViews_.size();
    std::uint64_t oldest = UINT64_MAX;
    std::function<void()> drop;
    for (auto& [session, slot] : slots_) {
      if (!slot.view) continue;
      ++views;
      if (slot.used < oldest) oldest = slot.used, drop = [&slot = slot] { slot.view.reset(); };
    }
    for (auto* kept : {&sharedViews_, &spareViews_})
      for (auto it = kept->begin(); it != kept->end(); ++it)
        if (it->second.used < oldest) oldest = it->second.used, drop = [kept, it] { kept->erase(it); };
    if (views <= kLiveViews) return;
    drop();
  }
}

// The participant's input moves the session's navigator (the window's arithmetic), each motion
// kept only when the eye stays within the trial's bounds; then the frame from exactly that camera.
// A session's first frame without input is the start frame warmNow rendered before it was asked
// for (the same pixels: a shareable view's frames depend on the camera alone, and a spare view
// rendered nothing else). Its hash and encoding are made by the HTTP thread that sends it: this
// thread only renders.
LiveAnswer LiveRenderer::render(const LiveRequest& request) {
  LiveAnswer a;
  a.status = LiveAnswer::Status::Frame;
  a.stagesMs.emplace_back("wait", std::chrono::duration<double, std::milli>(LiveClock::now() - request.submitted).count());
  auto start = LiveClock::now();
  Slot& slot = slots_[request.session];
  if (slot.trial != request.trial) {
    slot = Slot{};
    slot.trial = request.trial;
  }
  slot.used = ++uses_;
  const LiveTrial& trial = *request.trial;
  const ViewInput& in = request.input;
  const bool shared = liveViewShareable(trial);
  std::shared_ptr<const Canvas> ready;  // the start frame, rendered before it was asked for
  if (slot.next == 0 && in.empty()) {
    const std::string key = liveViewKey(trial);
    if (const auto it = sharedViews_.find(key); shared && it != sharedViews_.end()) ready = it->second.start;
    if (const auto it = spareViews_.find(key); !shared && !slot.view && it != spareViews_.end()) {
      slot.view = std::move(it->second.view);
      ready = it->second.start;
      spareViews_.erase(it);
    }
  }
  if (!shared && !slot.view) {
    slot.view = newView(trial);
    if (slot.lens) slot.view->pointAt(*slot.lens);  // a view dropped for others: made again with the lens where it was
  }
  LiveView& view = shared ? sharedView(trial, slot.used) : *slot.view;
  if (!slot.navigator) slot.navigator = view.navigator();  // the trial's start (a view's own navigator never moves)
  a.stagesMs.emplace_back("build", msSince(start));
  start = LiveClock::now();
  steer(*slot.navigator, trial, in);
  if (in.point && view.pointAt(*in.point)) slot.lens = glm::clamp(*in.point, glm::vec2(0.0f), glm::vec2(1.0f));
  a.frame.index = slot.next++;
  a.frame.camera = slot.navigator->camera();
  a.frame.lens = slot.lens;
  a.frame.input = in.describe();
  a.stagesMs.emplace_back("steer", msSince(start));
  start = LiveClock::now();
  a.pixels = ready ? ready : std::make_shared<const Canvas>(view.frameFrom(a.frame.camera));  // never the cached frame(): the exact camera logged
  a.stagesMs.emplace_back("render", msSince(start));
  dropLeastRecentlyUsedViews();
  return a;
}

}  // namespace tlab::study
