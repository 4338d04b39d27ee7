#include "study/serve/render_worker.hpp"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "core/image.hpp"
#include "core/sha256.hpp"
#include "study/run/camera_navigator.hpp"
#include "study/run/live_view.hpp"
#include "study/serve/gl_thread.hpp"

namespace tlab::study {

RenderWorker::RenderWorker(std::string directory, std::vector<render::BuiltinSceneSpec> catalog, OnlineSpec online, int liveRenderers)
    : directory_(std::move(directory)), catalog_(std::move(catalog)), online_(std::move(online)) {
  if (online_.live)
    for (int i = 0; i < std::max(1, liveRenderers); ++i) live_.push_back(std::make_unique<LiveRenderer>(kLiveFramesPerSecond));
  thread_ = startGlThread(
      [this](const gpu::GpuContext& context) {
        info_ = context.info();
        painter_ = std::make_unique<TextPainter>();
        library_ = std::make_unique<StimulusLibrary>(directory_, catalog_, *painter_);
      },
      [this] { loop(); });
}

RenderWorker::~RenderWorker() { stopGlThread(mutex_, stopping_, wake_, thread_); }

void RenderWorker::loop() {
  for (;;) {
    std::function<void()> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return !jobs_.empty() || stopping_; });
      if (jobs_.empty()) break;
      job = std::move(jobs_.front());
      jobs_.pop_front();
    }
    job();
  }
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

// A live trial's renderers are made here, ahead of its first frame: while the study is prepared
// (the first time a stimulus is seen) every LiveRenderer makes them before the server listens;
// later (a spare taken, a view dropped) they are made again when no frame is due.
TrialImages RenderWorker::images(const PlannedTrial& trial, const PreparedTrial& prepared) {
  const auto [images, first] = onGlThread([&] {
    const std::string key = trial.stimulus.text();
    if (const auto it = trialImages_.find(key); it != trialImages_.end()) return std::pair{it->second, false};
    TrialImages images;
    if (prepared.floorPlanImage) images.floorPlanSha256 = writeImage(prepared.floorPlanImage->toImage());
    if (trial.navigation != Navigation::None && online_.live) images.live = true;
    else if (trial.navigation == Navigation::Orbit) images.turntable = renderTurntable(trial, prepared);
    return std::pair{trialImages_.emplace(key, images).first->second, true};
  });
  if (images.live && prepared.scene) {
    const LiveTrial live{prepared.scene, trial.stimulus, trial.navigation, prepared.camera};
    std::vector<std::future<void>> made;
    for (auto& renderer : live_) made.push_back(renderer->warm(live, first));
    if (first)
      for (auto& m : made) m.get();
  }
  return images;
}

LiveAnswer RenderWorker::liveFrame(LiveRequest request) {
  LiveRenderer* renderer = nullptr;
  {
    std::lock_guard lock(mutex_);
    if (stopping_ || live_.empty()) return LiveAnswer{};
    auto [it, added] = liveOf_.emplace(request.session, nextLive_);  // sessions dealt to the renderers in turn
    if (added) nextLive_ = (nextLive_ + 1) % live_.size();
    renderer = live_[it->second].get();
  }
  return renderer->frame(std::move(request));
}

std::optional<std::string> RenderWorker::imagePath(const std::string& sha256) const {
  std::lock_guard lock(mutex_);
  const auto it = paths_.find(sha256);
  if (it == paths_.end()) return std::nullopt;
  return it->second;
}

}  // namespace tlab::study
