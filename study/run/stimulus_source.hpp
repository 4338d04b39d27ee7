#pragma once
// StimulusSource: where the session flow gets what a planned trial shows and scores. The
// StimulusLibrary renders on the calling thread's GL context; a server hands the calls to the one
// thread that owns its context (study/serve/render_worker.hpp).
#include "study/design/session_plan.hpp"

namespace tlab::study {

struct PreparedTrial;

class StimulusSource {
 public:
  virtual ~StimulusSource() = default;
  // Throws with a one-line message naming the scene, style or task when one of them fails.
  virtual PreparedTrial prepare(const PlannedTrial& trial) = 0;
};

}  // namespace tlab::study
