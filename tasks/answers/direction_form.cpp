// A direction (the gauge figure: Koenderink, van Doorn & Kappers 1992; Cole et al. 2009): typed as
// 'x,y,z' in world coordinates, given in the window and the page by dragging the gauge. Scored by
// the angle between the answer and the true normal, in degrees, with the slant and tilt errors.
#include <cmath>
#include <cstdio>

#include "tasks/answer_parser.hpp"
#include "tasks/answers/forms.hpp"
#include "tasks/gauge_frame.hpp"

namespace tlab::tasks {

namespace {

constexpr double kPi = 3.14159265358979323846;

double measurement(const Question& q, const std::string& key) {
  for (const auto& [k, v] : q.measurements)
    if (k == key) return v;
  throw AnswerFormatError(q.task + ": the question has no measurement '" + key + "'");
}

std::string directionText(glm::dvec3 n) {
  n = glm::normalize(n);
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.6f,%.6f,%.6f", n.x, n.y, n.z);
  return buf;
}

// A unit vector perpendicular to n.
glm::dvec3 perpendicular(glm::dvec3 n) {
  const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(n, a));
}

class DirectionForm final : public AnswerForm {
 public:
  AnswerKind kind() const override { return AnswerKind::Direction; }
  const char* name() const override { return "direction"; }
  const char* format() const override { return "a direction 'x,y,z' in world coordinates (the surface normal; any length)"; }
  GroundTruth parse(const Question&, const std::string& text) const override { return parseDirection(text); }
  std::string text(const Question&, const GroundTruth& value) const override { return directionText(std::get<glm::dvec3>(value)); }
  void score(const Question& q, const GroundTruth& given, Score& s) const override {
    const glm::dvec3 answer = std::get<glm::dvec3>(given), truth = std::get<glm::dvec3>(q.truth);
    s.error = angleDegrees(answer, truth);
    s.correct = *s.error <= q.correctWithin;
    const GaugeFrame frame = gaugeFrameOf(q);
    const glm::dvec2 a = slantTiltOf(frame, answer), t = slantTiltOf(frame, truth);
    s.measures = {{"slant_error", a.x - t.x}, {"tilt_error", tiltDifference(a.y, t.y)}};
  }
  Widget widget(const Question& q) const override {
    Widget w;
    w.kind = WidgetKind::Gauge;
    w.at = q.points.at(0).pixel;
    w.radiusPixels = measurement(q, "gauge-radius-px");
    w.startSlant = measurement(q, "start-slant");
    w.startTilt = measurement(q, "start-tilt");
    return w;
  }
  std::string fromInput(const Question& q, const WidgetInput& input) const override {
    if (const auto* g = std::get_if<GaugeSetting>(&input)) {
      if (!(std::isfinite(g->slantDegrees) && std::isfinite(g->tiltDegrees)) || g->slantDegrees < 0.0 || g->slantDegrees > 90.0)
        throw AnswerFormatError("answer: a gauge's slant must be from 0 to 90 degrees", "refusal.slant");
      return directionText(normalFromSlantTilt(gaugeFrameOf(q), g->slantDegrees, g->tiltDegrees));
    }
    return AnswerForm::fromInput(q, input);
  }
  std::optional<std::string> bookletField() const override { return std::nullopt; }
  // A guess: a direction uniform over the hemisphere facing the viewer.
  std::string guess(const Question& q, core::SeededRandom& random) const override {
    const double cosSlant = double(random.uniform()), tilt = 360.0 * double(random.uniform());
    return directionText(normalFromSlantTilt(gaugeFrameOf(q), std::acos(cosSlant) * 180.0 / kPi, tilt));
  }
  // A seen normal: the truth tilted by a Gaussian offset in its tangent plane of angular sd
  // gauge_degrees · (1 + gauge_growth · (1 − v)) at visibility v, turned to face the viewer.
  std::string known(const Question& q, core::SeededRandom& random, double visibility, const AnswerNoise& noise) const override {
    const glm::dvec3 truth = std::get<glm::dvec3>(q.truth);
    const double sd = noise.gaugeDegrees * (1.0 + noise.gaugeGrowth * (1.0 - visibility)) * kPi / 180.0;
    const glm::dvec3 t1 = perpendicular(truth), t2 = glm::cross(truth, t1);
    const double z1 = standardNormal(random);
    const double z2 = standardNormal(random);
    glm::dvec3 n = glm::normalize(truth + std::tan(std::min(sd, 1.5)) * (z1 * t1 + z2 * t2));
    const glm::dvec3 w = gaugeFrameOf(q).w;
    if (glm::dot(n, w) < 0.0) n -= 2.0 * glm::dot(n, w) * w;
    return directionText(n);
  }
  int layersInFront(const Question& q) const override { return int(measurement(q, "layer")) - 1; }
};

}  // namespace

const AnswerForm& directionForm() {
  static const DirectionForm form;
  return form;
}

}  // namespace tlab::tasks
