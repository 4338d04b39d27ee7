#include "tasks/pattern/pattern_task.hpp"

#include <stdexcept>

#include "tasks/counting/counting_task.hpp"
#include "tasks/letter_patterns.hpp"
#include "tasks/probe_helpers.hpp"
#include "tasks/scene_targets.hpp"

namespace tlab::tasks {

std::vector<SettingSpec> PatternTask::settingSpecs() const {
  auto specs = commonSettings();
  specs.push_back(SettingSpec::text("kind", "", "the pattern is formed by objects of this kind (e.g. cone); empty: objects with the Target role"));
  specs.push_back(SettingSpec::number("tolerance", "0.25", "how far (in grid cells) a target may be from its letter cell", 0, 100));
  return specs;
}

std::vector<Question> PatternTask::probe(const ProbeRequest& request) const {
  requireOneQuestion(name(), request.count);
  const std::string kind = request.settings.text("kind");
  const double tolerance = request.settings.number("tolerance");
  const auto targets = selectTargets(request.scene, kind);
  const ViewGeometry view(request.camera, request.width, request.height);
  Question q;
  std::vector<glm::dvec2> floor;
  for (const auto i : targets) {
    const glm::dvec3 where = surfaceCentroid(request.scene.objects[i].mesh);
    q.points.push_back(probePoint(view, request.scene.objects[i].name, "target", where, int(i)));
    floor.push_back(floorPlanPoint(where));
  }
  const auto letters = matchingLetters(floor, tolerance);
  if (letters.size() != 1)
    throw std::runtime_error(name() + ": the " + std::to_string(targets.size()) + " " + describeTargets(kind) + " form " +
                             (letters.empty() ? std::string("none") : std::to_string(letters.size())) +
                             " of the letters C, K, R, X, Y on the floor plan (need exactly one)");
  q.task = name();
  q.text = "Which letter do the targets form on the floor: C, K, R, X or Y?";
  q.textKey = "question.pattern";
  q.answerKind = AnswerKind::Letter;
  q.truth = std::string(1, letters[0]);
  q.timeLimitSeconds = request.settings.number("time-limit");
  q.checks = {{"letters matching the targets (unique)", double(letters.size()), 1.0}};
  return {q};
}

}  // namespace tlab::tasks
