#pragma once
// Live views online: the frames of an orbit or walk trial that `tlab serve` renders on its GL
// worker from the participant's input (ViewInput), one LiveView per live trial of a session.
// LiveFrameQueue is the worker's to-do list of frames, kept apart from GL so its rules are
// unit-tested: every session has at most one frame waiting — a request superseded by newer input
// of the same session is answered "superseded" and dropped, its input handed on to the newer one —
// and sessions are served in turn (round-robin: a session waits behind every other session that
// asked before it), each at most framesPerSecond frames a second (a request that comes sooner waits
// for its turn, and may be superseded meanwhile).
#include <chrono>
#include <deque>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/scene/camera.hpp"
#include "renderer/scene/scene.hpp"
#include "study/design/navigation.hpp"
#include "study/design/session_plan.hpp"
#include "study/run/camera_navigator.hpp"
#include "study/run/frame_log.hpp"
#include "study/serve/view_input.hpp"

namespace tlab::study {

using LiveClock = std::chrono::steady_clock;

// What a live trial's screen lets its page see: the trial's scene, style and start camera. The
// page names none of it; the server looks it up from the screen on show.
struct LiveTrial {
  std::shared_ptr<const render::Scene> scene;
  StimulusKey stimulus;
  Navigation navigation = Navigation::None;
  render::Camera start;
};

// Where a live trial's eye may go: within 1.5 × max(R, |eye₀ − c|) of the centre c of the scene's
// bounding sphere (radius R; eye₀ the start). Orbiting never leaves it (the orbit keeps or
// shortens the distance); walking without collision stops at it. Finite numbers only.
bool withinLiveBounds(const LiveTrial& trial, const render::Camera& camera);
// The participant's drag and keys moving a live trial's navigator (the window's arithmetic), each
// motion made only when the eye stays within the bounds above.
void steer(CameraNavigator& navigator, const LiveTrial& trial, const ViewInput& input);
// Whether the trial's style has a lens that follows the cursor (dynamic, mode = active), as LiveView decides.
bool lensFollowsCursor(const StimulusKey& stimulus);

// The renderer a live trial's frames come from is kept per key: the scene, the style with its
// settings, the size, the navigation and the start camera (LiveTrial).
std::string liveViewKey(const LiveTrial& trial);
// Whether sessions may share one renderer for `trial`: its frames depend only on the camera, never
// on the frames before (every style but dynamic, whose group order is state across frames, seed 004
// Alg. 1 line 1, and whose lens is the session's own).
bool liveViewShareable(const LiveTrial& trial);

struct LiveRequest {
  std::string session;  // the participant's token
  std::shared_ptr<const LiveTrial> trial;
  ViewInput input;
  LiveClock::time_point submitted = LiveClock::now();  // when the server took the request
};

// What a frame cost, stage by stage, in milliseconds (the Server-Timing header: "wait", "build",
// "steer", "render" on the GL worker; then "hash", "encode", ... where it is sent).
using StageTimes = std::vector<std::pair<std::string, double>>;

struct LiveAnswer {
  enum class Status { Frame, Superseded };
  Status status = Status::Superseded;
  LiveFrame frame;                      // index, camera, lens and input (the SHA-256 and shownNs are set where it is sent)
  std::shared_ptr<const Canvas> pixels;  // the frame as rendered
  StageTimes stagesMs;                   // what it cost on the GL worker
};

class LiveFrameQueue {
 public:
  explicit LiveFrameQueue(double framesPerSecond) : interval_(std::chrono::duration_cast<LiveClock::duration>(std::chrono::duration<double>(1.0 / framesPerSecond))) {}

  std::future<LiveAnswer> submit(LiveRequest request);
  struct Taken {
    LiveRequest request;
    std::promise<LiveAnswer> answer;
  };
  // The next frame to render at `now`; nullopt when none is due.
  std::optional<Taken> take(LiveClock::time_point now);
  // When the next waiting frame is due (nullopt: nothing waits).
  std::optional<LiveClock::time_point> nextDue() const;
  // Answers every waiting request "superseded" (the server stops).
  void clear();

 private:
  struct Pending {
    LiveRequest request;
    std::promise<LiveAnswer> answer;
  };
  LiveClock::duration interval_;
  std::map<std::string, Pending> pending_;
  std::deque<std::string> order_;                         // sessions with a waiting frame, oldest first
  std::map<std::string, LiveClock::time_point> started_;  // when each session's last frame was taken
};

}  // namespace tlab::study
