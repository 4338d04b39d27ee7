#include "study/serve/render_worker.hpp"

#include <chrono>
#include <filesystem>

#include "core/image.hpp"
#include "core/sha256.hpp"
#include "study/run/camera_navigator.hpp"
#include "study/run/live_view.hpp"

namespace tlab::study {

RenderWorker::RenderWorker(std::string directory, std::vector<render::BuiltinSceneSpec> catalog, OnlineSpec online)
    : directory_(std::move(directory)), catalog_(std::move(catalog)), online_(std::move(online)) {
  std::promise<void> ready;
  auto started = ready.get_future();
  thread_ = std::thread([this, &ready] { loop(ready); });
  try {
    started.get();  // the context's error, if it could not be made
  } catch (...) {
    thread_.join();
    throw;
  }
}

RenderWorker::~RenderWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void RenderWorker::loop(std::promise<void>& ready) {
  std::unique_ptr<gpu::GpuContext> context;
  try {
    context = gpu::createHeadlessContext();
    info_ = context->info();
    painter_ = std::make_unique<TextPainter>();
    library_ = std::make_unique<StimulusLibrary>(directory_, catalog_, *painter_);
    ready.set_value();
  } catch (...) {
    ready.set_exception(std::current_exception());
    return;
  }
  for (;;) {
    std::function<void()> job;
    std::optional<LiveFrameQueue::Taken> frame;
    {
      std::unique_lock lock(mutex_);
      for (;;) {  // preparation first; then a live frame that is due; then a warm-up; else wait
        if (!jobs_.empty() || stopping_) break;
        if ((frame = liveQueue_.take(LiveClock::now()))) break;
        if (!idleJobs_.empty()) break;
        if (const auto due = liveQueue_.nextDue()) wake_.wait_until(lock, *due);
        else wake_.wait(lock);
      }
      if (!frame && jobs_.empty() && stopping_) break;
      auto& from = jobs_.empty() ? idleJobs_ : jobs_;
      if (!frame) {
        job = std::move(from.front());
        from.pop_front();
      }
    }
    if (job) job();
    if (frame) {
      try {
        frame->answer.set_value(renderLive(frame->request));
      } catch (...) {
        frame->answer.set_exception(std::current_exception());
      }
    }
  }
  {
    std::lock_guard lock(mutex_);
    liveQueue_.clear();
  }
  liveSlots_.clear();  // their renderers' GL objects go while the context is current
  sharedViews_.clear();
  spareViews_.clear();
  library_.reset();
  painter_.reset();
}

// Prepared trials are kept here too, so that the many session threads of a burst of arrivals
// (each preparing its whole plan) do not queue on the one GL thread for what is already made.
PreparedTrial RenderWorker::prepare(const PlannedTrial& trial) {
  const std::string key = preparedTrialKey(trial);
  {
    std::lock_guard lock(mutex_);
    if (const auto it = prepared_.find(key); it != prepared_.end()) return it->second;
  }
  PreparedTrial prepared = onGlThread([&] { return library_->prepare(trial); });
  std::lock_guard lock(mutex_);
  paths_.emplace(prepared.stimulusSha256, prepared.stimulusPath);
  prepared_.emplace(key, prepared);
  return prepared;
}

std::string RenderWorker::writeImage(const core::Image& image) {
  const std::vector<std::uint8_t> png = core::encodePng(image);
  const std::string sha = core::sha256Hex(png);
  const std::string path = (std::filesystem::path(directory_) / (sha + ".png")).string();
  if (!std::filesystem::exists(path)) {
    std::filesystem::create_directories(directory_);
    core::writeFileAtomically(path, png);
  }
  std::lock_guard lock(mutex_);
  paths_.emplace(sha, path);
  return sha;
}

// Views around the target at `azimuths` × `elevations` (Elmqvist's orbiting, pre-rendered): the
// start view is azimuth 0 at the middle elevation; elevations spread evenly over the configured
// range, each kept within the navigator's ±80°.
Turntable RenderWorker::renderTurntable(const PlannedTrial& trial, const PreparedTrial& prepared) {
  Turntable t;
  t.azimuths = online_.turntableAzimuths;
  t.elevations = online_.turntableElevations;
  t.startElevation = (t.elevations - 1) / 2;
  LiveView view(prepared.scene, trial.stimulus, Navigation::Orbit, prepared.camera);
  for (int e = 0; e < t.elevations; ++e) {
    const double elevation = t.elevations == 1 ? 0.0 : online_.turntableElevationDegrees * (double(e) / double(t.elevations - 1) - 0.5);
    for (int a = 0; a < t.azimuths; ++a) {
      const double azimuth = 360.0 * double(a) / double(t.azimuths);
      CameraNavigator navigator(Navigation::Orbit, prepared.camera, 1.0f, 1.0f);
      navigator.drag(azimuth, -elevation);  // 1° per "pixel": the window's own orbit arithmetic
      const Canvas frame = view.frameFrom(navigator.camera());
      t.views.push_back({a, e, azimuth, elevation, writeImage(frame.toImage()), navigator.describe()});
    }
  }
  return t;
}

TrialImages RenderWorker::images(const PlannedTrial& trial, const PreparedTrial& prepared) {
  return onGlThread([&] {
    const std::string key = trial.stimulus.text();
    if (const auto it = trialImages_.find(key); it != trialImages_.end()) {
      if (it->second.live && prepared.scene) {  // its views made again (a spare taken, a view dropped) when nothing else waits
        std::lock_guard lock(mutex_);
        if (idleJobs_.size() < kLiveViews) idleJobs_.push_back([this, live = LiveTrial{prepared.scene, trial.stimulus, trial.navigation, prepared.camera}] { warmLive(live); });
      }
      return it->second;
    }
    TrialImages images;
    if (prepared.floorPlanImage) images.floorPlanSha256 = writeImage(prepared.floorPlanImage->toImage());
    if (trial.navigation != Navigation::None && online_.live) images.live = true;
    else if (trial.navigation == Navigation::Orbit) images.turntable = renderTurntable(trial, prepared);
    if (images.live && prepared.scene) warmLive(LiveTrial{prepared.scene, trial.stimulus, trial.navigation, prepared.camera});
    return trialImages_.emplace(key, images).first->second;
  });
}

LiveAnswer RenderWorker::liveFrame(LiveRequest request) {
  std::future<LiveAnswer> answer;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return LiveAnswer{};
    answer = liveQueue_.submit(std::move(request));
  }
  wake_.notify_one();
  return answer.get();
}

namespace {

double msSince(LiveClock::time_point start) { return std::chrono::duration<double, std::milli>(LiveClock::now() - start).count(); }

std::unique_ptr<LiveView> newView(const LiveTrial& t) { return std::make_unique<LiveView>(t.scene, t.stimulus, t.navigation, t.start); }

}  // namespace

RenderWorker::KeptView RenderWorker::makeWarmView(const LiveTrial& trial) {
  KeptView k{newView(trial), nullptr, ++liveUses_};
  k.start = std::make_shared<const Canvas>(k.view->frameFrom(k.view->navigator().camera()));  // as a session's frame 0
  return k;
}

void RenderWorker::warmLive(const LiveTrial& trial) {
  const std::string key = liveViewKey(trial);
  auto& kept = liveViewShareable(trial) ? sharedViews_ : spareViews_;
  const auto it = kept.find(key);
  if (it != kept.end() && it->second.start) return;
  std::size_t views = sharedViews_.size() + spareViews_.size();
  for (const auto& [session, slot] : liveSlots_) views += slot.view ? 1 : 0;
  if (it == kept.end() && views >= kLiveViews) return;  // no room: made when a session asks
  if (it == kept.end()) kept.emplace(key, makeWarmView(trial));
  else it->second.start = std::make_shared<const Canvas>(it->second.view->frameFrom(it->second.view->navigator().camera()));
}

LiveView& RenderWorker::sharedView(const LiveTrial& trial, std::uint64_t use) {
  KeptView& kept = sharedViews_[liveViewKey(trial)];
  if (!kept.view) kept.view = newView(trial);
  kept.used = use;
  return *kept.view;
}

// The least recently used views go while more than kLiveViews are kept (a session's own, a shared
// one, a spare).
void RenderWorker::dropLeastRecentlyUsedViews() {
  for (;;) {
    std::size_t views = sharedViews_.size() + spareViews_.size();
    std::uint64_t oldest = UINT64_MAX;
    std::function<void()> drop;
    for (auto& [session, slot] : liveSlots_) {
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
// A session's first frame without input is the start frame warmLive rendered before it was asked
// for (the same pixels: a shareable view's frames depend on the camera alone, and a spare view
// rendered nothing else). Its hash and PNG are made by the HTTP thread that sends it: the GL worker
// only renders.
LiveAnswer RenderWorker::renderLive(const LiveRequest& request) {
  LiveAnswer a;
  a.status = LiveAnswer::Status::Frame;
  a.stagesMs.emplace_back("wait", std::chrono::duration<double, std::milli>(LiveClock::now() - request.submitted).count());
  auto start = LiveClock::now();
  LiveSlot& slot = liveSlots_[request.session];
  if (slot.trial != request.trial) {
    slot = LiveSlot{};
    slot.trial = request.trial;
  }
  slot.used = ++liveUses_;
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

std::optional<std::string> RenderWorker::imagePath(const std::string& sha256) const {
  std::lock_guard lock(mutex_);
  const auto it = paths_.find(sha256);
  if (it == paths_.end()) return std::nullopt;
  return it->second;
}

}  // namespace tlab::study
