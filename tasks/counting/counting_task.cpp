#include "tasks/counting/counting_task.hpp"

#include <stdexcept>

#include "tasks/probe_helpers.hpp"
#include "tasks/scene_targets.hpp"

namespace tlab::tasks {

void requireOneQuestion(const std::string& task, int count) {
  if (count != 1)
    throw std::invalid_argument(task + ": a scene-level task asks one question per scene (use --count 1; vary the scene for more)");
}

std::vector<SettingSpec> CountingTask::settingSpecs() const {
  auto specs = commonSettings();
  specs.push_back(SettingSpec::text("kind", "", "count objects of this kind (name without its number); empty: objects with the Target role"));
  return specs;
}

std::vector<Question> CountingTask::probe(const ProbeRequest& request) const {
  requireOneQuestion(name(), request.count);
  const std::string kind = request.settings.text("kind");
  const auto targets = selectTargets(request.scene, kind);
  if (targets.empty())
    throw std::runtime_error(name() + ": the scene has no " + describeTargets(kind) + " (relative error needs at least one)");
  const ViewGeometry view(request.camera, request.width, request.height);
  Question q;
  q.task = name();
  q.text = "How many " + (kind.empty() ? std::string("targets") : kind + " objects") + " are there?";
  q.textKey = kind.empty() ? "question.counting" : "question.counting_kind";
  if (!kind.empty()) q.textArgs = {{"kind", kind}};
  q.answerKind = AnswerKind::Count;
  for (const auto i : targets)
    q.points.push_back(probePoint(view, request.scene.objects[i].name, "target", surfaceCentroid(request.scene.objects[i].mesh), int(i)));
  q.truth = std::int64_t(targets.size());
  q.timeLimitSeconds = request.settings.number("time-limit");
  q.checks = {{"targets in the scene (>= 1 for a relative error)", double(targets.size()), 1.0}};
  return {q};
}

}  // namespace tlab::tasks
