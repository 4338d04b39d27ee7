#pragma once
// The gauge figure task (Koenderink, van Doorn & Kappers 1992; Cole et al. 2009, "How well do line
// drawings depict shape?"): the participant turns a gauge — a disk with a stick along its normal —
// until it lies on the surface at the probe. The ground truth is the surface's unit normal there
// (the mesh's smooth normal, the one shading uses), facing the viewer, in world coordinates, with its
// slant and tilt in the view (tasks/gauge_frame.hpp); the score is the angle between answer and
// truth in degrees, with the slant and tilt errors. The probe lies on a chosen layer of a transparent
// stack (layer=1: the front surface); probes near a silhouette (slant over max-slant), a crease or a
// layer change within the gauge's footprint are rejected (SurfaceProbe::continuity).
#include "tasks/task.hpp"

namespace tlab::tasks {

class GaugeFigureTask : public Task {
 public:
  std::string name() const override { return "gauge-figure"; }
  std::string summary() const override { return "turn a gauge until it lies on the surface; error = angle to the true normal"; }
  std::vector<SettingSpec> settingSpecs() const override;
  std::vector<Question> probe(const ProbeRequest& request) const override;
};

}  // namespace tlab::tasks
