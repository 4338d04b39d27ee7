#include "tasks/question.hpp"

#include "tasks/answer_form.hpp"

namespace tlab::tasks {

const char* answerKindName(AnswerKind kind) { return answerForm(kind).name(); }

const char* answerFormat(AnswerKind kind) { return answerForm(kind).format(); }

std::vector<std::string> Question::labels() const {
  std::vector<std::string> out;
  for (const auto& p : points) out.push_back(p.label);
  return out;
}

}  // namespace tlab::tasks
