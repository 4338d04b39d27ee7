#pragma once
// The relative-depth task (Koenderink & van Doorn's depth-order judgements; Todd & Norman): two
// marked points, "which is nearer?". Each lies on a layer chosen by the settings (layer-a, layer-b;
// 1 = the front surface of a transparent stack); the ground truth is the label of the point nearer
// along the viewing direction. Pairs whose depths differ by less than min-depth-gap are rejected as
// ambiguous, and so are points whose surface is not smooth around them (SurfaceProbe::continuity).
#include "tasks/task.hpp"

namespace tlab::tasks {

class RelativeDepthTask : public Task {
 public:
  std::string name() const override { return "relative-depth"; }
  std::string summary() const override { return "which of two marked points is nearer to the viewer"; }
  std::vector<SettingSpec> settingSpecs() const override;
  std::vector<Question> probe(const ProbeRequest& request) const override;
};

}  // namespace tlab::tasks
