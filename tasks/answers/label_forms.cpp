// Label answers: one of the candidate points (Carnecky Task 3, relative depth), a set of the marked
// points (Carnecky Task 2), and one of the pattern letters (Elmqvist T2).
#include "tasks/answer_parser.hpp"
#include "tasks/answers/forms.hpp"
#include "tasks/letter_patterns.hpp"
#include "tasks/scoring.hpp"

namespace tlab::tasks {

namespace {

std::vector<ProbePoint> pointsWithRole(const Question& q, const std::string& role) {
  std::vector<ProbePoint> out;
  for (const auto& p : q.points)
    if (p.role == role) out.push_back(p);
  return out;
}

class LabelForm final : public AnswerForm {
 public:
  AnswerKind kind() const override { return AnswerKind::Label; }
  const char* name() const override { return "label"; }
  const char* format() const override { return "one of the candidate labels (e.g. 'X')"; }
  std::string hint() const override { return "Click the marked point on the picture (or its button below)."; }
  GroundTruth parse(const Question& q, const std::string& text) const override { return parseLabel(text, labelsWithRole(q, "candidate")); }
  std::string text(const Question&, const GroundTruth& value) const override { return std::get<std::string>(value); }
  void score(const Question& q, const GroundTruth& given, Score& s) const override { s.correct = given == q.truth; }
  Widget widget(const Question& q) const override {
    Widget w;
    w.kind = WidgetKind::PickLabel;
    w.marks = pointsWithRole(q, "candidate");
    return w;
  }
  std::string guess(const Question& q, core::SeededRandom& random) const override {
    auto labels = labelsWithRole(q, "candidate");
    if (labels.empty()) labels = q.labels();
    return labels[random.below(std::uint32_t(labels.size()))];
  }
};

class LabelSetForm final : public AnswerForm {
 public:
  AnswerKind kind() const override { return AnswerKind::LabelSet; }
  const char* name() const override { return "label-set"; }
  const char* format() const override { return "labels separated by commas, or 'none' for no label (e.g. 'C,E')"; }
  std::string hint() const override { return "Click every marked point you choose (on the picture or below; click again to undo), then Done."; }
  GroundTruth parse(const Question& q, const std::string& text) const override { return parseLabelSet(text, q.labels()); }
  std::string text(const Question&, const GroundTruth& value) const override {
    std::string out;
    for (const auto& l : std::get<std::set<std::string>>(value)) out += (out.empty() ? "" : ",") + l;
    return out.empty() ? "none" : out;
  }
  void score(const Question& q, const GroundTruth& given, Score& s) const override {
    s.correct = given == q.truth;
    s.partialCredit = jaccardIndex(std::get<std::set<std::string>>(given), std::get<std::set<std::string>>(q.truth));
  }
  void scoreMissing(const Question&, Score& s) const override { s.partialCredit = 0.0; }
  Widget widget(const Question& q) const override {
    Widget w;
    w.kind = WidgetKind::PickLabels;
    w.marks = pointsWithRole(q, "mark");
    return w;
  }
  std::string guess(const Question& q, core::SeededRandom& random) const override {
    std::string out;
    for (const auto& l : labelsWithRole(q, "mark"))
      if (random.below(2)) out += (out.empty() ? "" : ",") + l;
    return out.empty() ? "none" : out;
  }
};

class LetterForm final : public AnswerForm {
 public:
  AnswerKind kind() const override { return AnswerKind::Letter; }
  const char* name() const override { return "letter"; }
  const char* format() const override { return "one of the letters C, K, R, X, Y"; }
  std::string hint() const override { return "Click the letter (or press its key)."; }
  GroundTruth parse(const Question&, const std::string& text) const override { return parseLetter(text); }
  std::string text(const Question&, const GroundTruth& value) const override { return std::get<std::string>(value); }
  void score(const Question& q, const GroundTruth& given, Score& s) const override { s.correct = given == q.truth; }
  Widget widget(const Question&) const override {
    Widget w;
    w.kind = WidgetKind::Buttons;
    for (const char l : patternLetters()) w.buttons.push_back(std::string(1, l));
    return w;
  }
  std::string guess(const Question&, core::SeededRandom& random) const override {
    const std::string letters = patternLetters();
    return std::string(1, letters[random.below(std::uint32_t(letters.size()))]);
  }
};

}  // namespace

const AnswerForm& labelForm() {
  static const LabelForm form;
  return form;
}

const AnswerForm& labelSetForm() {
  static const LabelSetForm form;
  return form;
}

const AnswerForm& letterForm() {
  static const LetterForm form;
  return form;
}

}  // namespace tlab::tasks
