#include "tasks/question.hpp"

namespace tlab::tasks {

const char* answerKindName(AnswerKind kind) {
  switch (kind) {
    case AnswerKind::LayerNumber: return "layer-number";
    case AnswerKind::LabelSet: return "label-set";
    case AnswerKind::Label: return "label";
    case AnswerKind::Count: return "count";
    case AnswerKind::FloorPoint: return "floor-point";
    case AnswerKind::Letter: return "letter";
  }
  return "?";
}

const char* answerFormat(AnswerKind kind) {
  switch (kind) {
    case AnswerKind::LayerNumber: return "a layer number: a whole number >= 1 (1 = front)";
    case AnswerKind::LabelSet: return "labels separated by commas, or 'none' for no label (e.g. 'C,E')";
    case AnswerKind::Label: return "one of the candidate labels (e.g. 'X')";
    case AnswerKind::Count: return "a count: a whole number >= 0";
    case AnswerKind::FloorPoint: return "a floor-plan point 'X,Z' in world units";
    case AnswerKind::Letter: return "one of the letters C, K, R, X, Y";
  }
  return "?";
}

std::vector<std::string> Question::labels() const {
  std::vector<std::string> out;
  for (const auto& p : points) out.push_back(p.label);
  return out;
}

}  // namespace tlab::tasks
