#include "tasks/task_registry.hpp"

#include <stdexcept>

#include "tasks/counting/counting_task.hpp"
#include "tasks/follow_boundary/follow_boundary_task.hpp"
#include "tasks/gauge_figure/gauge_figure_task.hpp"
#include "tasks/layer_index/layer_index_task.hpp"
#include "tasks/nearest_point/nearest_point_task.hpp"
#include "tasks/pattern/pattern_task.hpp"
#include "tasks/relative_depth/relative_depth_task.hpp"
#include "tasks/target_discovery/target_discovery_task.hpp"

namespace tlab::tasks {

std::vector<std::string> taskNames() {
  return {"layer-index", "follow-boundary", "nearest-point", "counting", "target-discovery", "pattern", "gauge-figure", "relative-depth"};
}

std::unique_ptr<Task> makeTask(const std::string& name) {
  if (name == "layer-index") return std::make_unique<LayerIndexTask>();
  if (name == "follow-boundary") return std::make_unique<FollowBoundaryTask>();
  if (name == "nearest-point") return std::make_unique<NearestPointTask>();
  if (name == "counting") return std::make_unique<CountingTask>();
  if (name == "target-discovery") return std::make_unique<TargetDiscoveryTask>();
  if (name == "pattern") return std::make_unique<PatternTask>();
  if (name == "gauge-figure") return std::make_unique<GaugeFigureTask>();
  if (name == "relative-depth") return std::make_unique<RelativeDepthTask>();
  std::string known;
  for (const auto& n : taskNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown task '" + name + "' (known: " + known + ")");
}

}  // namespace tlab::tasks
