// Fuzz target: typed answers → values, for every answer kind, and task settings "key=value"
// (`--set`, experiment files). The first byte selects the kind; rejections must be
// AnswerFormatError / std::invalid_argument with a message.
// fuzz-sources: tasks/answer_parser.cpp tasks/task_settings.cpp
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "tasks/answer_parser.hpp"
#include "tasks/task_settings.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  tlab::tasks::Question q;
  q.answerKind = static_cast<tlab::tasks::AnswerKind>(data[0] % 6);
  q.points = {{"A", "candidate", {}, {}, 0}, {"B", "candidate", {}, {}, 1}, {"X", "probe", {}, {}, -1}};
  try {
    tlab::tasks::parseAnswer(q, text);
  } catch (const tlab::tasks::AnswerFormatError&) {
  }
  try {
    const tlab::tasks::TaskSettings settings("fuzz", tlab::tasks::commonSettings(), {text});
    settings.number("time-limit");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
