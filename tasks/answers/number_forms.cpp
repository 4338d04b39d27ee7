// Whole-number answers: a layer number (Carnecky Task 1) and a count (Elmqvist T1, T4).
#include <algorithm>
#include <cmath>

#include "tasks/answer_parser.hpp"
#include "tasks/answers/forms.hpp"
#include "tasks/scoring.hpp"

namespace tlab::tasks {

namespace {

class WholeNumberForm : public AnswerForm {
 public:
  std::string text(const Question&, const GroundTruth& value) const override { return std::to_string(std::get<std::int64_t>(value)); }
  Widget widget(const Question&) const override {
    Widget w;
    w.kind = WidgetKind::Number;
    w.minimum = minimum();
    return w;
  }

 protected:
  virtual std::int64_t minimum() const = 0;
};

class LayerNumberForm final : public WholeNumberForm {
 public:
  AnswerKind kind() const override { return AnswerKind::LayerNumber; }
  const char* name() const override { return "layer-number"; }
  const char* format() const override { return "a layer number: a whole number >= 1 (1 = front)"; }
  std::string hint() const override { return "Type the layer number (1 is the front surface) and press Enter."; }
  GroundTruth parse(const Question&, const std::string& text) const override { return parseLayerNumber(text); }
  void score(const Question& q, const GroundTruth& given, Score& s) const override { s.correct = given == q.truth; }
  std::string guess(const Question& q, core::SeededRandom& random) const override {
    const auto truth = std::get<std::int64_t>(q.truth);
    return std::to_string(1 + random.below(std::uint32_t(std::max<std::int64_t>(truth + 1, 3))));
  }
  int layersInFront(const Question& q) const override { return int(std::get<std::int64_t>(q.truth) - 1); }

 protected:
  std::int64_t minimum() const override { return 1; }
};

// A missing count is scored as if the participant had counted nothing, so that the totals over
// trials stay defined (every missed target is an error).
class CountForm final : public WholeNumberForm {
 public:
  AnswerKind kind() const override { return AnswerKind::Count; }
  const char* name() const override { return "count"; }
  const char* format() const override { return "a count: a whole number >= 0"; }
  std::string hint() const override { return "Type the number and press Enter."; }
  GroundTruth parse(const Question&, const std::string& text) const override { return parseCount(text); }
  void score(const Question& q, const GroundTruth& given, Score& s) const override {
    s.correct = given == q.truth;
    s.error = relativeError(std::get<std::int64_t>(given), std::get<std::int64_t>(q.truth));
  }
  void scoreMissing(const Question& q, Score& s) const override { s.error = relativeError(0, std::get<std::int64_t>(q.truth)); }
  // A guessed count is a noisy estimate around the truth (sd 30 %, at least 1).
  std::string guess(const Question& q, core::SeededRandom& random) const override {
    const double truth = double(std::get<std::int64_t>(q.truth));
    const double estimate = truth + standardNormal(random) * std::max(1.0, 0.3 * truth);
    return std::to_string(std::max<std::int64_t>(0, std::llround(estimate)));
  }

 protected:
  std::int64_t minimum() const override { return 0; }
};

}  // namespace

const AnswerForm& layerNumberForm() {
  static const LayerNumberForm form;
  return form;
}

const AnswerForm& countForm() {
  static const CountForm form;
  return form;
}

}  // namespace tlab::tasks
