#include "study/run/session_wording.hpp"

#include <cmath>
#include <set>

namespace tlab::study {

std::string countOf(long n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

std::string durationText(double seconds, const ParticipantTexts& texts) {
  if (seconds >= 120.0 || (seconds >= 60.0 && std::fmod(seconds, 60.0) == 0.0))
    return texts.amount("duration.minutes", std::round(seconds / 6.0) / 10.0);
  return texts.amount("duration.seconds", std::round(seconds * 10.0) / 10.0);
}

std::string taskIntroduction(const SessionPlan& plan, std::size_t index, const std::string& instructions, const ParticipantTexts& texts) {
  const PlannedTrial& first = plan.trials[index];
  long n = 0;
  for (std::size_t i = index; i < plan.trials.size() && plan.trials[i].taskId == first.taskId && plan.trials[i].phase == first.phase; ++i) ++n;
  std::string text = instructions + "\n\n" + texts.count(first.phase == Phase::Training ? "intro.practice" : "intro.trials", n);
  if (first.timeLimitSeconds > 0.0 && std::isfinite(first.timeLimitSeconds))
    text += " " + texts.count("intro.limit", n, {{"duration", durationText(first.timeLimitSeconds, texts)}});
  return text;
}

std::string breakText(const SessionPlan& plan, std::size_t done, const BreakSpec& spec, const ParticipantTexts& texts) {
  long trials = 0;
  std::set<int> blocks;
  for (std::size_t i = done + 1; i < plan.trials.size(); ++i)
    if (plan.trials[i].phase == Phase::Test) {
      ++trials;
      blocks.insert(plan.trials[i].block);
    }
  const std::string left = spec.blocks ? texts.count("break.blocks_left", long(blocks.size()), {{"trials", texts.count("count.trials", trials)}})
                                       : texts.count("break.trials_left", trials);
  return spec.text + "\n\n" + left;
}

std::string questionWording(const tasks::Question& question, const ParticipantTexts& texts) {
  return question.textKey.empty() || !texts.has(question.textKey) ? question.text : texts.format(question.textKey, question.textArgs);
}

std::string refusalWording(const tasks::AnswerFormatError& refusal, const ParticipantTexts& texts) {
  if (!refusal.key().empty() && texts.has(refusal.key())) return texts.format(refusal.key(), refusal.args());
  const std::string message = refusal.what();
  return message.rfind("answer: ", 0) == 0 ? message.substr(8) : message;
}

}  // namespace tlab::study
