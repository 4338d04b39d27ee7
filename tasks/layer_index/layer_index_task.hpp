#pragma once
// Carnecky Sec. 8.1, Task 1 "layer index": "specify on which layer the surface silhouette at the
// given point is located". Probes lie on silhouette edges (Fig. 2: interior silhouettes and
// boundaries); the ground truth is LayerGroundTruth's exact layer; probes whose 3 × 3 pixel
// neighbourhood disagrees are rejected as ambiguous.
#include "tasks/task.hpp"

namespace tlab::tasks {

class LayerIndexTask : public Task {
 public:
  std::string name() const override { return "layer-index"; }
  std::string summary() const override { return "the layer (1 = front) of a silhouette point"; }
  std::vector<SettingSpec> settingSpecs() const override;
  std::vector<Question> probe(const ProbeRequest& request) const override;
};

}  // namespace tlab::tasks
