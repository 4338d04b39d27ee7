#include "tasks/target_discovery/target_discovery_task.hpp"

#include <stdexcept>

#include "tasks/counting/counting_task.hpp"
#include "tasks/probe_helpers.hpp"
#include "tasks/scene_targets.hpp"

namespace tlab::tasks {

std::vector<SettingSpec> TargetDiscoveryTask::settingSpecs() const {
  auto specs = commonSettings();
  specs.push_back(SettingSpec::text("kind", "", "the target is the one object of this kind; empty: the one object with the Target role"));
  specs.push_back(SettingSpec::number("correct-within", "0", "error distance (world units) counted as correct; 0: 5 % of the scene's diameter", 0, 1e+30));
  return specs;
}

std::vector<Question> TargetDiscoveryTask::probe(const ProbeRequest& request) const {
  requireOneQuestion(name(), request.count);
  const std::string kind = request.settings.text("kind");
  const auto targets = selectTargets(request.scene, kind);
  if (targets.size() != 1)
    throw std::runtime_error(name() + ": needs exactly one of the " + describeTargets(kind) + ", the scene has " +
                             std::to_string(targets.size()));
  const ViewGeometry view(request.camera, request.width, request.height);
  const auto& target = request.scene.objects[targets[0]];
  const glm::dvec3 where = surfaceCentroid(target.mesh);
  const double within = request.settings.number("correct-within");
  Question q;
  q.task = name();
  q.text = "Find the unique target and mark its position on the floor plan.";
  q.textKey = "question.target_discovery";
  q.answerKind = AnswerKind::FloorPoint;
  q.points = {probePoint(view, target.name, "target", where, int(targets[0]))};
  q.truth = floorPlanPoint(where);
  q.correctWithin = within > 0.0 ? within : 0.05 * 2.0 * double(request.scene.boundingSphere().radius);
  q.timeLimitSeconds = request.settings.number("time-limit");
  q.checks = {{"objects that are the target (unique)", 1.0, 1.0}};
  return {q};
}

}  // namespace tlab::tasks
