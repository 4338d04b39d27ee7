#include "study/run/session_wording.hpp"

#include <cmath>
#include <cstdio>
#include <set>

namespace tlab::study {

std::string countOf(long n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

std::string durationText(double seconds) {
  char number[32];
  if (seconds >= 120.0 || (seconds >= 60.0 && std::fmod(seconds, 60.0) == 0.0)) {
    std::snprintf(number, sizeof number, "%g", std::round(seconds / 6.0) / 10.0);
    return std::string(number) + (std::string(number) == "1" ? " minute" : " minutes");
  }
  std::snprintf(number, sizeof number, "%g", std::round(seconds * 10.0) / 10.0);
  return std::string(number) + (std::string(number) == "1" ? " second" : " seconds");
}

std::string taskIntroduction(const SessionPlan& plan, std::size_t index, const std::string& instructions) {
  const PlannedTrial& first = plan.trials[index];
  long n = 0;
  for (std::size_t i = index; i < plan.trials.size() && plan.trials[i].taskId == first.taskId && plan.trials[i].phase == first.phase; ++i) ++n;
  std::string text = instructions + "\n\n";
  text += first.phase == Phase::Training ? "There " + std::string(n == 1 ? "is " : "are ") + countOf(n, "practice trial", "practice trials")
                                         : "There " + std::string(n == 1 ? "is " : "are ") + countOf(n, "trial", "trials");
  text += " of this kind now";
  if (first.timeLimitSeconds > 0.0 && std::isfinite(first.timeLimitSeconds))
    text += std::string(n == 1 ? "; it has" : "; each has") + " a time limit of " + durationText(first.timeLimitSeconds) + " (a countdown shows the time left)";
  return text + ".";
}

std::string breakText(const SessionPlan& plan, std::size_t done, const BreakSpec& spec) {
  long trials = 0;
  std::set<int> blocks;
  for (std::size_t i = done + 1; i < plan.trials.size(); ++i)
    if (plan.trials[i].phase == Phase::Test) {
      ++trials;
      blocks.insert(plan.trials[i].block);
    }
  const std::string left = spec.blocks ? countOf(long(blocks.size()), "block", "blocks") + " (" + countOf(trials, "trial", "trials") + ")"
                                       : countOf(trials, "trial", "trials");
  return spec.text + "\n\n" + left + (trials == 1 && !spec.blocks ? " is" : (spec.blocks && blocks.size() == 1 ? " is" : " are")) + " left.";
}

}  // namespace tlab::study
