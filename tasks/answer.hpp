#pragma once
// A participant's raw answer to one question: the typed text (none if the time ran out or the
// question was skipped) and the time taken.
#include <optional>
#include <string>

namespace tlab::tasks {

struct Answer {
  std::optional<std::string> text;     // std::nullopt: missing
  std::optional<double> seconds;       // time taken; std::nullopt: not measured
};

}  // namespace tlab::tasks
