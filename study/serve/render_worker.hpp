#pragma once
// RenderWorker: the one thread of a server that owns a GL context. Stimuli, floor plans and
// turntable views are rendered there (StimulusLibrary needs a current context and is not
// thread-safe); every session thread asks through prepare(), which queues the call and waits.
// Everything a study shows is prepared before the server listens, so during the study these calls
// only look up what is cached. Images are indexed by SHA-256: the server serves nothing else.
// Live trials (orbit, walk) are the exception: their frames are rendered during the study by the
// worker's LiveRenderers (live_renderer.hpp: threads with their own GL contexts, each session's
// frames on one of them), whose renderers for a live trial are made while its screen is prepared.
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "renderer/gpu/gpu_context.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "study/design/experiment.hpp"
#include "study/run/live_view.hpp"
#include "study/run/stimulus_library.hpp"
#include "study/serve/live_frames.hpp"
#include "study/serve/live_renderer.hpp"
#include "study/serve/trial_page.hpp"

namespace tlab::study {

class RenderWorker : public StimulusSource {
 public:
  // `liveRenderers`: how many threads render live frames at once (each its own GL context).
  RenderWorker(std::string directory, std::vector<render::BuiltinSceneSpec> catalog, OnlineSpec online, int liveRenderers = 1);
  ~RenderWorker() override;
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  PreparedTrial prepare(const PlannedTrial& trial) override;
  // The floor plan and turntable of a trial (rendered once per stimulus key).
  TrialImages images(const PlannedTrial& trial, const PreparedTrial& prepared);
  // The next frame of a live trial after `request.input`, rendered by the session's LiveRenderer
  // (waits for it); "superseded" when newer input of the same session came before it was begun.
  LiveAnswer liveFrame(LiveRequest request);
  static constexpr double kLiveFramesPerSecond = 30.0;
  const gpu::GpuInfo& gpuInfo() const { return info_; }
  // The PNG file of an image this worker made or prepared, by SHA-256 name; nullopt otherwise.
  std::optional<std::string> imagePath(const std::string& sha256) const;

 private:
  template <class F>
  auto onGlThread(F job) -> decltype(job()) {
    auto task = std::make_shared<std::packaged_task<decltype(job())()>>(std::move(job));
    auto result = task->get_future();
    {
      std::lock_guard lock(mutex_);
      jobs_.push_back([task] { (*task)(); });
    }
    wake_.notify_one();
    return result.get();
  }
  void loop();  // the GL thread's: jobs until stopped
  std::string writeImage(const core::Image& image);  // GL thread
  Turntable renderTurntable(const PlannedTrial& trial, const PreparedTrial& prepared);  // GL thread
  std::string directory_;
  std::vector<render::BuiltinSceneSpec> catalog_;
  OnlineSpec online_;
  gpu::GpuInfo info_;
  std::unique_ptr<TextPainter> painter_;      // GL thread
  std::unique_ptr<StimulusLibrary> library_;  // GL thread
  std::map<std::string, TrialImages> trialImages_;  // GL thread: stimulus key → images
  std::vector<std::unique_ptr<LiveRenderer>> live_;
  std::map<std::string, std::size_t> liveOf_;  // session token → its LiveRenderer (guarded by mutex_)
  std::size_t nextLive_ = 0;                   // the next session's LiveRenderer (guarded by mutex_)
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  std::map<std::string, std::string> paths_;  // sha256 → file (guarded by mutex_)
  std::map<std::string, PreparedTrial> prepared_;  // preparedTrialKey → trial (guarded by mutex_)
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace tlab::study
