#pragma once
// LiveRenderer: a thread with its own GL context that renders the frames of live trials (orbit,
// walk) from the participants' input. `tlab serve` runs one or more beside its RenderWorker (which
// prepares stimuli); each session's frames come from one of them, so that on a machine where a
// frame's render is partly serial (llvmpipe) several render at once. Per session it keeps where
// the camera is, the next frame's index and the lens; the renderers themselves are made before a
// frame is asked for: when a trial's screen is prepared (warm), a shareable trial's view is made
// and its start frame rendered once for every session, and a dynamic trial gets a spare view with
// its start frame rendered, which the next session to start that trial takes. At most kLiveViews
// views are kept, the least recently used dropped first and made again when a session asks.
// Frames wait in a LiveFrameQueue (one per session, sessions in turn, at most framesPerSecond each).
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "renderer/gpu/gpu_context.hpp"
#include "study/run/live_view.hpp"
#include "study/serve/live_frames.hpp"

namespace tlab::study {

class LiveRenderer {
 public:
  // Makes the GL context on its thread; throws its error.
  explicit LiveRenderer(double framesPerSecond);
  ~LiveRenderer();
  LiveRenderer(const LiveRenderer&) = delete;
  LiveRenderer& operator=(const LiveRenderer&) = delete;

  // The next frame of a live trial after `request.input`, rendered on this thread (waits for it);
  // "superseded" when newer input of the same session came before it was begun.
  LiveAnswer frame(LiveRequest request);
  // Makes `trial`'s view and start frame ahead: before any frame (`urgent`, while a study is
  // prepared), or when no frame is due. The future is ready when it is done (or skipped).
  std::future<void> warm(const LiveTrial& trial, bool urgent);
  static constexpr std::size_t kLiveViews = 16;  // views kept at once; the least recently used goes first

 private:
  void loop();  // the thread's: warm-ups and frames until stopped
  LiveAnswer render(const LiveRequest& request);  // the thread's
  void warmNow(const LiveTrial& trial);           // the thread's
  // One view of a live trial: the renderer, and the start frame it rendered first (not yet shown;
  // kept for the next session to start the trial), counted for the LRU.
  struct KeptView {
    std::unique_ptr<LiveView> view;
    std::shared_ptr<const Canvas> start;
    std::uint64_t used = 0;
  };
  KeptView makeWarmView(const LiveTrial& trial);
  // One session's live trial: where its camera is, the next frame's index, the lens where the
  // cursor last put it, and its own view when the style keeps state across frames (dynamic).
  struct Slot {
    std::shared_ptr<const LiveTrial> trial;
    std::optional<CameraNavigator> navigator;
    int next = 0;
    std::optional<glm::vec2> lens;
    std::unique_ptr<LiveView> view;
    std::uint64_t used = 0;
  };
  LiveView& sharedView(const LiveTrial& trial, std::uint64_t use);
  void dropLeastRecentlyUsedViews();

  // The thread's:
  std::map<std::string, Slot> slots_;             // session token → its live trial
  std::map<std::string, KeptView> sharedViews_;   // liveViewKey → the view sessions share
  std::map<std::string, KeptView> spareViews_;    // liveViewKey → a dynamic trial's next session's view
  std::uint64_t uses_ = 0;
  // Guarded by mutex_:
  LiveFrameQueue queue_;
  std::deque<std::function<void()>> jobs_;  // warm-ups that a study's preparation waits for
  std::deque<std::function<void()>> idle_;  // warm-ups when no frame is due
  bool stopping_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace tlab::study
