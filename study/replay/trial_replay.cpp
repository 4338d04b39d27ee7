#include "study/replay/trial_replay.hpp"

#include <memory>
#include <optional>

#include "study/run/live_view.hpp"
#include "study/run/stimulus_library.hpp"

namespace tlab::study {

int ReplayCheck::identical() const {
  int n = 0;
  for (const auto& f : frames) n += f.identical ? 1 : 0;
  return n;
}

std::string ReplayCheck::summary() const {
  return std::to_string(identical()) + " of " + std::to_string(frames.size()) + " frames identical";
}

std::string whyDifferent(const LoggedTrial& trial, std::size_t i, const ReplayRenderer& self) {
  const LoggedFrame& f = trial.frames[i];
  std::vector<std::string> causes;
  const int expected = i == 0 || f.frame.index == 0 ? 0 : trial.frames[i - 1].frame.index + 1;
  if (f.frame.index != expected)
    causes.push_back("frames " + std::to_string(expected) + " to " + std::to_string(f.frame.index - 1) +
                     " were rendered but not logged (the renderer's state across frames differs)");
  const auto s = trial.sessions.find(f.session);
  const FrameSession stored = s == trial.sessions.end() ? FrameSession{} : s->second;
  const std::string session = "session " + std::to_string(f.session);
  if (stored.glRenderer.empty()) causes.push_back(session + " stored no GL renderer");
  else if (stored.glRenderer != self.glRenderer)
    causes.push_back(session + " rendered with GL '" + stored.glRenderer + "', this replay with '" + self.glRenderer + "'");
  if (stored.tlabVersion.empty()) causes.push_back(session + " stored no tlab version");
  else if (stored.tlabVersion != self.tlabVersion)
    causes.push_back(session + " ran tlab " + stored.tlabVersion + ", this replay " + self.tlabVersion);
  if (causes.empty())
    return "same GL ('" + self.glRenderer + "') and tlab version (" + self.tlabVersion +
           ") as the session: the logged hash or camera was changed, or the renderer is not deterministic here";
  std::string why;
  for (const auto& c : causes) why += (why.empty() ? "" : "; ") + c;
  return why;
}

ReplayCheck replayTrial(const LoggedTrial& trial, const std::vector<render::BuiltinSceneSpec>& catalog, const ReplayRenderer& self,
                        const std::function<void(std::size_t, const Canvas&, const FrameCheck&)>& each) {
  const std::shared_ptr<const render::Scene> scene = loadStimulusScene(trial.plan.stimulus, catalog);
  ReplayCheck check;
  std::optional<LiveView> view;
  for (std::size_t i = 0; i < trial.frames.size(); ++i) {
    const LiveFrame& logged = trial.frames[i].frame;
    // A new showing (index 0) renders on a new LiveView, as the front end that showed it did.
    if (!view || logged.index == 0) view.emplace(scene, trial.plan.stimulus, trial.plan.navigation, logged.camera);
    const Canvas picture = view->frameFrom(logged.camera, logged.lens);
    FrameCheck f;
    f.replayedSha256 = framePixelsSha256(picture);
    f.identical = f.replayedSha256 == logged.sha256;
    if (!f.identical) f.why = whyDifferent(trial, i, self);
    if (each) each(i, picture, f);
    check.frames.push_back(std::move(f));
  }
  return check;
}

}  // namespace tlab::study
