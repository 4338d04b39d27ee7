#include "tasks/gauge_figure/gauge_figure_task.hpp"

#include <string>

#include "core/seeded_random.hpp"
#include "tasks/gauge_frame.hpp"
#include "tasks/probe_helpers.hpp"
#include "tasks/surface_probe.hpp"

namespace tlab::tasks {

std::vector<SettingSpec> GaugeFigureTask::settingSpecs() const {
  auto specs = commonSettings();
  specs.push_back(SettingSpec::count("layer", "1", "the surface the gauge lies on: 1 = the front one, k = the k-th along the line of sight", 1, 1000));
  specs.push_back(SettingSpec::number("gauge-radius-px", "18", "the gauge disk's radius in stimulus pixels (also the footprint checked for ambiguity)", 2, 10000));
  specs.push_back(SettingSpec::number("max-slant", "75", "largest slant (degrees) of a probed surface: steeper is too near a silhouette", 0, 90));
  specs.push_back(SettingSpec::number("max-normal-spread", "15", "largest angle (degrees) between the normals within the gauge's footprint (creases, layer changes)", 0, 180));
  specs.push_back(SettingSpec::number("correct-within", "15", "angle error (degrees) counted as correct", 0, 180));
  specs.push_back(SettingSpec::number("min-separation-px", "40", "minimum pixel distance between the probes of different questions", 0, 100000));
  specs.push_back(SettingSpec::count("attempts", "2000", "candidate probes tried per question before giving up", 1, 1000000));
  return specs;
}

namespace {

std::string questionText(int layer) {
  if (layer == 1) return "Turn the gauge until its disk lies flat on the front surface.";
  return "Turn the gauge until its disk lies flat on surface " + std::to_string(layer) + " from the front.";
}

}  // namespace

std::vector<Question> GaugeFigureTask::probe(const ProbeRequest& request) const {
  requirePositiveCount(name(), request.count);
  const TaskSettings& s = request.settings;
  const int layer = int(s.number("layer"));
  const double radius = s.number("gauge-radius-px"), maxSlant = s.number("max-slant"), maxSpread = s.number("max-normal-spread");
  const double separation = s.number("min-separation-px");
  const int attempts = int(s.number("attempts"));
  const double margin = radius + 2.0;
  if (2.0 * margin >= std::min(request.width, request.height)) throw std::invalid_argument(name() + ": the image is too small for the gauge");

  const ViewGeometry view(request.camera, request.width, request.height);
  const SurfaceProbe surfaces(request.scene, view);
  core::SeededRandom random(request.seed);
  std::vector<Question> questions;
  std::vector<glm::dvec2> taken;
  for (int q = 0; q < request.count; ++q) {
    bool found = false;
    for (int a = 0; a < attempts && !found; ++a) {
      const glm::dvec2 pixel = randomPixel(random, request.width, request.height, margin);
      const double gap = nearestPixelDistance(pixel, taken);
      if (gap < separation) continue;
      const auto centre = surfaces.at(pixel, layer);
      if (!centre) continue;
      const GaugeFrame frame = gaugeFrame(view, centre->point);
      const glm::dvec2 slantTilt = slantTiltOf(frame, centre->normal);
      if (slantTilt.x > maxSlant) continue;
      const auto spread = surfaces.continuity(*centre, pixel, radius, maxSpread);
      if (!spread) continue;
      Question question;
      question.task = name();
      question.number = q + 1;
      question.text = questionText(layer);
      question.textKey = layer == 1 ? "question.gauge_figure_front" : "question.gauge_figure_layer";
      if (layer > 1) question.textArgs = {{"layer", std::to_string(layer)}};
      question.answerKind = AnswerKind::Direction;
      question.points = {probePoint(view, "A", "gauge", centre->point, centre->object)};
      question.truth = centre->normal;
      question.correctWithin = s.number("correct-within");
      question.timeLimitSeconds = s.number("time-limit");
      keepGaugeFrame(question, frame);
      question.checks = {{"slant of the surface (degrees)", slantTilt.x, maxSlant},
                         {"largest normal angle within the gauge's footprint (degrees)", *spread, maxSpread}};
      if (!taken.empty()) question.checks.push_back({"pixel distance to earlier probes", gap, separation});
      // The gauge starts at a seeded orientation (logged with the question), away from the truth's
      // answer by chance only: slant uniform in [0, 70), tilt uniform in [0, 360).
      const double startSlant = 70.0 * double(random.uniform()), startTilt = 360.0 * double(random.uniform());
      question.measurements = {{"layer", double(layer)},          {"depth", view.depth(centre->point)},
                               {"slant", slantTilt.x},            {"tilt", slantTilt.y},
                               {"gauge-radius-px", radius},       {"start-slant", startSlant},
                               {"start-tilt", startTilt}};
      questions.push_back(std::move(question));
      taken.push_back(pixel);
      found = true;
    }
    if (!found)
      throwTooFew(name(), questions.size(), request.count,
                  "places on layer " + std::to_string(layer) +
                      " whose surface is smooth over the gauge's footprint and not steeper than max-slant; try fewer questions, "
                      "a smaller gauge-radius-px or min-separation-px, or another view");
  }
  return questions;
}

}  // namespace tlab::tasks
