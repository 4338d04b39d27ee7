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
      for (;;) {  // preparation first; then a live frame that is due; else wait for either
        if (!jobs_.empty() || stopping_) break;
        if ((frame = liveQueue_.take(LiveClock::now()))) break;
        if (const auto due = liveQueue_.nextDue()) wake_.wait_until(lock, *due);
        else wake_.wait(lock);
      }
      if (!frame && jobs_.empty()) break;
      if (!frame) {
        job = std::move(jobs_.front());
        jobs_.pop_front();
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
    if (const auto it = trialImages_.find(key); it != trialImages_.end()) return it->second;
    TrialImages images;
    if (prepared.floorPlanImage) images.floorPlanSha256 = writeImage(prepared.floorPlanImage->toImage());
    if (trial.navigation != Navigation::None && online_.live) images.live = true;
    else if (trial.navigation == Navigation::Orbit) images.turntable = renderTurntable(trial, prepared);
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

}  // namespace

// The participant's input moves the session's navigator (the window's arithmetic), each motion
// kept only when the eye stays within the trial's bounds; then the frame from exactly that camera.
// Its hash and PNG are made by the HTTP thread that sends it: the GL worker only renders.
LiveAnswer RenderWorker::renderLive(const LiveRequest& request) {
  LiveSlot& slot = liveSlots_[request.session];
  if (slot.trial != request.trial) {
    slot = LiveSlot{};
    slot.trial = request.trial;
  }
  slot.used = ++liveUses_;
  if (!slot.view) {
    slot.view = std::make_unique<LiveView>(request.trial->scene, request.trial->stimulus, request.trial->navigation, request.trial->start);
    if (slot.navigator) slot.view->navigator() = *slot.navigator;  // a view dropped for others: made again where it was
    if (slot.lens) slot.view->pointAt(*slot.lens);
  }
  LiveView& view = *slot.view;
  const ViewInput& in = request.input;
  steer(view.navigator(), *request.trial, in);
  slot.navigator = view.navigator();
  if (in.point && view.pointAt(*in.point)) slot.lens = glm::clamp(*in.point, glm::vec2(0.0f), glm::vec2(1.0f));
  LiveAnswer a;
  a.status = LiveAnswer::Status::Frame;
  a.frame.index = slot.next++;
  a.frame.camera = view.navigator().camera();
  a.frame.lens = slot.lens;
  a.frame.input = in.describe();
  const auto start = LiveClock::now();
  a.pixels = std::make_shared<const Canvas>(view.frameFrom(a.frame.camera));  // never the cached frame(): the exact camera logged
  a.renderMs = msSince(start);
  std::size_t views = 0;
  for (const auto& [session, other] : liveSlots_) views += other.view ? 1 : 0;
  for (; views > kLiveViews; --views) {  // the least recently used view goes
    LiveSlot* oldest = nullptr;
    for (auto& [session, other] : liveSlots_)
      if (other.view && (!oldest || other.used < oldest->used)) oldest = &other;
    oldest->view.reset();
  }
  return a;
}

std::optional<std::string> RenderWorker::imagePath(const std::string& sha256) const {
  std::lock_guard lock(mutex_);
  const auto it = paths_.find(sha256);
  if (it == paths_.end()) return std::nullopt;
  return it->second;
}

}  // namespace tlab::study
