#include "tasks/scoring.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "tasks/answer_form.hpp"

namespace tlab::tasks {

double jaccardIndex(const std::set<std::string>& answer, const std::set<std::string>& truth) {
  std::size_t common = 0;
  for (const auto& a : answer) common += truth.count(a);
  const std::size_t all = answer.size() + truth.size() - common;
  return all == 0 ? 1.0 : double(common) / double(all);
}

double relativeError(std::int64_t answer, std::int64_t truth) {
  if (truth <= 0) throw std::invalid_argument("relative error needs a true count > 0");
  return double(std::llabs(answer - truth)) / double(truth);
}

double errorDistance(glm::dvec2 answer, glm::dvec2 truth) { return glm::length(answer - truth); }

namespace {
std::int64_t sumOfTargets(const std::vector<CountingTrial>& trials) {
  std::int64_t targets = 0;
  for (const auto& t : trials) targets += t.truth;
  if (targets <= 0) throw std::invalid_argument("relative error totals need at least one target");
  return targets;
}
}  // namespace

double sumOfErrorsOverSumOfTargets(const std::vector<CountingTrial>& trials) {
  std::int64_t errors = 0;
  for (const auto& t : trials) errors += std::llabs(t.answer - t.truth);
  return double(errors) / double(sumOfTargets(trials));
}

double errorOfSumsOverSumOfTargets(const std::vector<CountingTrial>& trials) {
  std::int64_t answers = 0;
  for (const auto& t : trials) answers += t.answer;
  const std::int64_t targets = sumOfTargets(trials);
  return double(std::llabs(answers - targets)) / double(targets);
}

bool withinTimeLimit(const Answer& answer, double timeLimitSeconds) {
  return !answer.seconds || *answer.seconds <= timeLimitSeconds;
}

namespace {

Score missing(const Question& q, const Answer& a, const char* note) {
  Score s;
  s.rawAnswer = a.text.value_or("");
  s.note = note;
  answerForm(q).scoreMissing(q, s);
  return s;
}

}  // namespace

Score scoreAnswer(const Question& q, const Answer& a) {
  if (!a.text) return missing(q, a, "missing");
  if (!withinTimeLimit(a, q.timeLimitSeconds)) return missing(q, a, "over the time limit");
  const AnswerForm& form = answerForm(q);
  const GroundTruth given = form.parse(q, *a.text);
  Score s;
  s.answered = true;
  s.rawAnswer = *a.text;
  form.score(q, given, s);
  s.value = s.correct ? 1.0 : 0.0;
  return s;
}

}  // namespace tlab::tasks
