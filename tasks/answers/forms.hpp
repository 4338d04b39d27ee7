#pragma once
// The shipped answer forms (one file each in tasks/answers/); answerForm() picks one by kind.
#include "tasks/answer_form.hpp"

namespace tlab::tasks {

const AnswerForm& layerNumberForm();
const AnswerForm& countForm();
const AnswerForm& labelForm();
const AnswerForm& labelSetForm();
const AnswerForm& letterForm();
const AnswerForm& floorPointForm();
const AnswerForm& directionForm();

// The labels of the question's points with this role, in order.
std::vector<std::string> labelsWithRole(const Question& q, const std::string& role);

}  // namespace tlab::tasks
