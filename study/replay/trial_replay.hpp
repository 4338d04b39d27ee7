#pragma once
// TrialReplay: the live frames of a LoggedTrial rendered again, in the order they were shown, from
// their logged cameras and lenses, through the same LiveView the window and the browser render
// with (its renderer's state across frames — the dynamic style's group order — builds up as it did
// live; a new showing of the trial, a frame with index 0, starts a new LiveView as the front ends
// did). Each picture's SHA-256 is compared with the logged one; where they differ, the check says
// what it suspects: another GL, another tlab version, frames rendered but not logged, or else a
// log that was changed. Needs a current GL context.
#include <functional>
#include <string>
#include <vector>

#include "renderer/scene/builtin_scenes.hpp"
#include "study/replay/logged_trial.hpp"
#include "study/run/canvas.hpp"

namespace tlab::study {

// The GL and tlab of this replay, compared with what each session stored.
struct ReplayRenderer {
  std::string glRenderer;
  std::string tlabVersion;
};

struct FrameCheck {
  std::string replayedSha256;
  bool identical = false;
  std::string why;  // why it likely differs (empty when identical)
};

struct ReplayCheck {
  std::vector<FrameCheck> frames;  // one per logged frame, in order
  int identical() const;
  // "7 of 7 frames identical"
  std::string summary() const;
};

// Renders every logged frame; `each` (may be empty) receives each frame's picture with its check.
ReplayCheck replayTrial(const LoggedTrial& trial, const std::vector<render::BuiltinSceneSpec>& catalog, const ReplayRenderer& self,
                        const std::function<void(std::size_t, const Canvas&, const FrameCheck&)>& each);

// Why logged frame `i` differs from its replay: what its session stored against this replay's GL
// and tlab, and whether frames before it were rendered but not logged.
std::string whyDifferent(const LoggedTrial& trial, std::size_t i, const ReplayRenderer& self);

}  // namespace tlab::study
