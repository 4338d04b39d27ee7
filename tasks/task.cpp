#include "tasks/task.hpp"

#include "tasks/scoring.hpp"

namespace tlab::tasks {

Score Task::score(const Question& question, const Answer& answer) const { return scoreAnswer(question, answer); }

}  // namespace tlab::tasks
