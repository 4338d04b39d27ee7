#include "tasks/relative_depth/relative_depth_task.hpp"

#include <array>
#include <cmath>

#include "core/seeded_random.hpp"
#include "tasks/probe_helpers.hpp"
#include "tasks/surface_probe.hpp"

namespace tlab::tasks {

std::vector<SettingSpec> RelativeDepthTask::settingSpecs() const {
  auto specs = commonSettings();
  specs.push_back(SettingSpec::count("layer-a", "1", "the surface point A lies on (1 = the front one)", 1, 1000));
  specs.push_back(SettingSpec::count("layer-b", "1", "the surface point B lies on (1 = the front one)", 1, 1000));
  specs.push_back(SettingSpec::number("min-depth-gap", "0.05", "smallest depth difference of the two points, as a share of the scene's diameter", 0, 1));
  specs.push_back(SettingSpec::number("min-distance-px", "40", "smallest pixel distance between A and B", 0, 100000));
  specs.push_back(SettingSpec::number("max-distance-px", "0", "largest pixel distance between A and B (0: no limit)", 0, 100000));
  specs.push_back(SettingSpec::number("footprint-px", "4", "radius (pixels) around each point over which its surface must be smooth", 0, 1000));
  specs.push_back(SettingSpec::number("max-normal-spread", "20", "largest normal angle (degrees) within a point's footprint", 0, 180));
  specs.push_back(SettingSpec::number("margin-px", "12", "minimum pixel distance of a point from the image border", 0, 100000));
  specs.push_back(SettingSpec::number("min-separation-px", "12", "minimum pixel distance between the points of different questions", 0, 100000));
  specs.push_back(SettingSpec::count("attempts", "2000", "candidate pairs tried per question before giving up", 1, 1000000));
  return specs;
}

std::vector<Question> RelativeDepthTask::probe(const ProbeRequest& request) const {
  requirePositiveCount(name(), request.count);
  const TaskSettings& s = request.settings;
  const std::array<int, 2> layers{int(s.number("layer-a")), int(s.number("layer-b"))};
  const double minGap = s.number("min-depth-gap") * 2.0 * double(request.scene.boundingSphere().radius);
  const double minDistance = s.number("min-distance-px"), maxDistance = s.number("max-distance-px");
  const double footprint = s.number("footprint-px"), maxSpread = s.number("max-normal-spread");
  const double margin = s.number("margin-px"), separation = s.number("min-separation-px");
  const int attempts = int(s.number("attempts"));

  const ViewGeometry view(request.camera, request.width, request.height);
  const SurfaceProbe surfaces(request.scene, view);
  core::SeededRandom random(request.seed);
  const auto candidate = [&](int layer) -> std::optional<std::pair<glm::dvec2, SurfaceSample>> {
    const glm::dvec2 pixel = randomPixel(random, request.width, request.height, margin);
    const auto sample = surfaces.at(pixel, layer);
    if (!sample || !surfaces.continuity(*sample, pixel, footprint, maxSpread)) return std::nullopt;
    return std::make_pair(pixel, *sample);
  };

  std::vector<Question> questions;
  std::vector<glm::dvec2> taken;
  for (int q = 0; q < request.count; ++q) {
    bool found = false;
    for (int a = 0; a < attempts && !found; ++a) {
      const auto first = candidate(layers[0]);
      if (!first) continue;
      const auto second = candidate(layers[1]);
      if (!second) continue;
      const double apart = glm::length(first->first - second->first);
      if (apart < minDistance || (maxDistance > 0.0 && apart > maxDistance)) continue;
      const double gap = std::min(nearestPixelDistance(first->first, taken), nearestPixelDistance(second->first, taken));
      if (gap < separation) continue;
      const double depthA = view.depth(first->second.point), depthB = view.depth(second->second.point);
      if (std::abs(depthA - depthB) < minGap) continue;
      Question question;
      question.task = name();
      question.number = q + 1;
      question.text = "Which of the two marked points, A or B, is nearer to you?";
      question.textKey = "question.relative_depth";
      question.answerKind = AnswerKind::Label;
      question.points = {probePoint(view, "A", "candidate", first->second.point, first->second.object),
                         probePoint(view, "B", "candidate", second->second.point, second->second.object)};
      question.truth = std::string(depthA < depthB ? "A" : "B");
      question.timeLimitSeconds = s.number("time-limit");
      question.checks = {{"depth difference of A and B (world units)", std::abs(depthA - depthB), minGap},
                         {"pixel distance of A and B", apart, minDistance}};
      if (!taken.empty()) question.checks.push_back({"pixel distance to earlier probes", gap, separation});
      question.measurements = {{"depth-A", depthA}, {"depth-B", depthB}, {"layer-A", double(layers[0])}, {"layer-B", double(layers[1])}};
      questions.push_back(std::move(question));
      taken.push_back(first->first);
      taken.push_back(second->first);
      found = true;
    }
    if (!found)
      throwTooFew(name(), questions.size(), request.count,
                  "pairs of smooth surface points on the chosen layers whose depths differ by at least min-depth-gap; try fewer "
                  "questions, a smaller min-depth-gap or min-distance-px, or another view");
  }
  return questions;
}

}  // namespace tlab::tasks
