#include "tasks/answer_form.hpp"

#include <cmath>
#include <cstdio>

#include "tasks/answer_parser.hpp"
#include "tasks/answers/forms.hpp"

namespace tlab::tasks {

const char* widgetName(WidgetKind kind) {
  switch (kind) {
    case WidgetKind::Number: return "number";
    case WidgetKind::PickLabel: return "pick-label";
    case WidgetKind::PickLabels: return "pick-labels";
    case WidgetKind::Buttons: return "buttons";
    case WidgetKind::FloorPlanPoint: return "floor-plan";
    case WidgetKind::Gauge: return "gauge";
  }
  return "?";
}

// The one place that maps an answer kind to its form.
const AnswerForm& answerForm(AnswerKind kind) {
  switch (kind) {
    case AnswerKind::LayerNumber: return layerNumberForm();
    case AnswerKind::LabelSet: return labelSetForm();
    case AnswerKind::Label: return labelForm();
    case AnswerKind::Count: return countForm();
    case AnswerKind::FloorPoint: return floorPointForm();
    case AnswerKind::Letter: return letterForm();
    case AnswerKind::Direction: return directionForm();
  }
  throw AnswerFormatError("answer: unknown answer kind");
}

namespace {
std::string joinedOrNone(const std::vector<std::string>& labels) {
  std::string text;
  for (const auto& l : labels) text += (text.empty() ? "" : ",") + l;
  return text.empty() ? "none" : text;
}
}  // namespace

// Typed text is taken as typed; picked labels are written as the label-set form writes them.
std::string AnswerForm::fromInput(const Question& q, const WidgetInput& input) const {
  std::string text;
  if (const auto* typed = std::get_if<TypedText>(&input)) text = typed->text;
  else if (const auto* picked = std::get_if<PickedLabels>(&input)) text = joinedOrNone(picked->labels);
  else throw AnswerFormatError(std::string("answer: a ") + name() + " answer is not given with this input");
  parse(q, text);  // refused here, not later
  return text;
}

std::string AnswerForm::known(const Question& q, core::SeededRandom&, double, const AnswerNoise&) const { return text(q, q.truth); }

std::vector<std::string> labelsWithRole(const Question& q, const std::string& role) {
  std::vector<std::string> out;
  for (const auto& p : q.points)
    if (p.role == role) out.push_back(p.label);
  return out;
}

double standardNormal(core::SeededRandom& random) {
  constexpr double kPi = 3.14159265358979323846;
  const double u1 = (double(random.uniform()) + 0x1p-25);
  const double u2 = double(random.uniform());
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

std::string answerNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

}  // namespace tlab::tasks
