// A place on the floor plan (Elmqvist T3): world (x, z), correct within the question's distance.
#include <algorithm>

#include "tasks/answer_parser.hpp"
#include "tasks/answers/forms.hpp"
#include "tasks/scoring.hpp"

namespace tlab::tasks {

namespace {

std::string pointText(double x, double z) { return answerNumber(x) + "," + answerNumber(z); }

// The truth with normal noise of sd `spread` on each axis, y's drawn first: the first (GCC) builds
// drew both within one expression of string operator+ calls, whose arguments C++ evaluates in an
// unspecified order (GCC last to first, clang first to last); one statement each keeps the
// simulated answers of those builds and makes a clang build give the same.
std::string scattered(const glm::dvec2& truth, double spread, core::SeededRandom& random) {
  const double dy = standardNormal(random) * spread;
  const double dx = standardNormal(random) * spread;
  return pointText(truth.x + dx, truth.y + dy);
}

class FloorPointForm final : public AnswerForm {
 public:
  AnswerKind kind() const override { return AnswerKind::FloorPoint; }
  const char* name() const override { return "floor-point"; }
  const char* format() const override { return "a floor-plan point 'X,Z' in world units"; }
  GroundTruth parse(const Question&, const std::string& text) const override { return parseFloorPoint(text); }
  std::string text(const Question&, const GroundTruth& value) const override {
    const auto p = std::get<glm::dvec2>(value);
    return pointText(p.x, p.y);
  }
  void score(const Question& q, const GroundTruth& given, Score& s) const override {
    s.error = errorDistance(std::get<glm::dvec2>(given), std::get<glm::dvec2>(q.truth));
    s.correct = *s.error <= q.correctWithin;
  }
  Widget widget(const Question&) const override {
    Widget w;
    w.kind = WidgetKind::FloorPlanPoint;
    return w;
  }
  // A click is written as a typed point is: one text form for the window, the page and the booklet.
  std::string fromInput(const Question& q, const WidgetInput& input) const override {
    if (const auto* click = std::get_if<PlanPoint>(&input)) return pointText(click->world.x, click->world.y);
    return AnswerForm::fromInput(q, input);
  }
  // Guesses scatter widely (sd 4 × the correct distance, at least 1); known places narrowly (0.25 ×).
  std::string guess(const Question& q, core::SeededRandom& random) const override {
    const glm::dvec2 truth = std::get<glm::dvec2>(q.truth);
    return scattered(truth, std::max(1.0, 4.0 * q.correctWithin), random);
  }
  std::string known(const Question& q, core::SeededRandom& random, double, const AnswerNoise&) const override {
    const glm::dvec2 truth = std::get<glm::dvec2>(q.truth);
    return scattered(truth, 0.25 * q.correctWithin, random);
  }
};

}  // namespace

const AnswerForm& floorPointForm() {
  static const FloorPointForm form;
  return form;
}

}  // namespace tlab::tasks
