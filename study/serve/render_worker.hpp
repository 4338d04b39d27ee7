#pragma once
// RenderWorker: the one thread of a server that owns a GL context. Stimuli, floor plans and
// turntable views are rendered there (StimulusLibrary needs a current context and is not
// thread-safe); every session thread asks through prepare(), which queues the call and waits.
// Everything a study shows is prepared before the server listens, so during the study these calls
// only look up what is cached. Images are indexed by SHA-256: the server serves nothing else.
// Live trials (orbit, walk) are the exception: their frames are rendered during the study, from a
// LiveView per session kept on this thread, when no preparation job waits (LiveFrameQueue: one
// frame per session at a time, sessions in turn, at most kLiveFramesPerSecond each).
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
#include "study/serve/trial_page.hpp"

namespace tlab::study {

class RenderWorker : public StimulusSource {
 public:
  RenderWorker(std::string directory, std::vector<render::BuiltinSceneSpec> catalog, OnlineSpec online);
  ~RenderWorker() override;
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  PreparedTrial prepare(const PlannedTrial& trial) override;
  // The floor plan and turntable of a trial (rendered once per stimulus key).
  TrialImages images(const PlannedTrial& trial, const PreparedTrial& prepared);
  // The next frame of a live trial after `request.input`, rendered on the GL thread (waits for it);
  // "superseded" when newer input of the same session came before it was begun.
  LiveAnswer liveFrame(LiveRequest request);
  static constexpr double kLiveFramesPerSecond = 30.0;
  static constexpr std::size_t kLiveViews = 16;  // renderers kept at once; the least recently used goes first
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
  void loop(std::promise<void>& ready);
  std::string writeImage(const core::Image& image);  // GL thread
  Turntable renderTurntable(const PlannedTrial& trial, const PreparedTrial& prepared);  // GL thread
  LiveAnswer renderLive(const LiveRequest& request);  // GL thread
  // A live trial's renderers are built before its first frame is asked for: when its screen is
  // prepared (images()), a shareable trial's view is made and its start frame rendered once for
  // every session; a dynamic trial gets a spare view with its start frame rendered, which the
  // next session to start that trial takes (kept within kLiveViews). GL thread.
  void warmLive(const LiveTrial& trial);
  // One view of a live trial on the GL thread: the renderer, and the start frame it rendered first
  // (not yet shown; kept for the next session to start the trial), counted for the LRU.
  struct KeptView {
    std::unique_ptr<LiveView> view;
    std::shared_ptr<const Canvas> start;
    std::uint64_t used = 0;
  };
  KeptView makeWarmView(const LiveTrial& trial);  // GL thread: built and its start frame rendered
  // One session's live trial on the GL thread: where its camera is, the next frame's index, the
  // lens where the cursor last put it, and its own view when the style keeps state across frames
  // (dynamic; else the trial's shared view renders: at most kLiveViews views of both kinds are
  // kept, the least recently used dropped first and made again when a session asks: the camera,
  // index and lens stay here).
  struct LiveSlot {
    std::shared_ptr<const LiveTrial> trial;
    std::optional<CameraNavigator> navigator;
    int next = 0;
    std::optional<glm::vec2> lens;
    std::unique_ptr<LiveView> view;
    std::uint64_t used = 0;
  };
  LiveView& sharedView(const LiveTrial& trial, std::uint64_t use);  // GL thread
  void dropLeastRecentlyUsedViews();                                 // GL thread

  std::string directory_;
  std::vector<render::BuiltinSceneSpec> catalog_;
  OnlineSpec online_;
  gpu::GpuInfo info_;
  std::unique_ptr<TextPainter> painter_;      // GL thread
  std::unique_ptr<StimulusLibrary> library_;  // GL thread
  std::map<std::string, TrialImages> trialImages_;  // GL thread: stimulus key → images
  std::map<std::string, LiveSlot> liveSlots_;        // GL thread: session token → its live trial
  std::map<std::string, KeptView> sharedViews_;      // GL thread: liveViewKey → the view sessions share
  std::map<std::string, KeptView> spareViews_;       // GL thread: liveViewKey → a dynamic trial's next session's view
  std::uint64_t liveUses_ = 0;                       // GL thread
  LiveFrameQueue liveQueue_{kLiveFramesPerSecond};   // guarded by mutex_
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  std::deque<std::function<void()>> idleJobs_;  // warm-ups: when no job waits and no live frame is due
  std::map<std::string, std::string> paths_;  // sha256 → file (guarded by mutex_)
  std::map<std::string, PreparedTrial> prepared_;  // preparedTrialKey → trial (guarded by mutex_)
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace tlab::study
