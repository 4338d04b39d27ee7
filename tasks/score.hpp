#pragma once
// The score of one trial: a numeric score (1 correct, 0 wrong or missing — Carnecky Sec. 8:
// "Missing answers were treated the same as wrong answers"), the task's error measure where it
// has one, a partial-credit measure reported separately, and the raw answer.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tlab::tasks {

struct Score {
  bool answered = false;                // false: missing, or given after the time limit
  bool correct = false;
  double value = 0.0;                   // 1 correct, 0 wrong or missing
  std::optional<double> partialCredit;  // follow-boundary: Jaccard index of the label sets
  std::optional<double> error;          // counting: relative error; target-discovery: error distance
  std::vector<std::pair<std::string, double>> measures;  // gauge figure: slant_error, tilt_error (degrees)
  std::string rawAnswer;                // the text as given ("" when missing)
  std::string note;                     // why an answer did not count ("missing", "over the time limit")
};

}  // namespace tlab::tasks
