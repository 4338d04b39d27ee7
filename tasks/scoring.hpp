#pragma once
// Pure score functions: each maps (ground truth, answer) to numbers, with no state.
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tasks/answer.hpp"
#include "tasks/question.hpp"
#include "tasks/score.hpp"

namespace tlab::tasks {

// |A ∩ T| / |A ∪ T|; 1 when both are empty. The partial credit of follow-boundary.
double jaccardIndex(const std::set<std::string>& answer, const std::set<std::string>& truth);

// Elmqvist Sec. 5 (T1, T4): |answer − truth| / truth; truth must be > 0.
double relativeError(std::int64_t answer, std::int64_t truth);

// Elmqvist Sec. 5 (T3): distance between the marked and the true floor-plan points.
double errorDistance(glm::dvec2 answer, glm::dvec2 truth);

struct CountingTrial {
  std::int64_t answer = 0;
  std::int64_t truth = 0;
};

// Totals over trials, Elmqvist Sec. 5: "the ratio between the absolute error and the total number
// of targets for all trials". Σ|aᵢ − tᵢ| / Σtᵢ (errors cannot cancel) ...
double sumOfErrorsOverSumOfTargets(const std::vector<CountingTrial>& trials);
// ... and the paper's literal wording, "the absolute difference between the sum of the targets and
// the sum of the subject answers": |Σaᵢ − Σtᵢ| / Σtᵢ (over- and under-counts cancel).
double errorOfSumsOverSumOfTargets(const std::vector<CountingTrial>& trials);

// True when the answer was given within the question's time limit (an unmeasured time counts).
bool withinTimeLimit(const Answer& answer, double timeLimitSeconds);

// Scores an answer against a question by its answer kind. A missing answer or one over the time
// limit scores 0 (Carnecky Sec. 8). Throws AnswerFormatError for a malformed answer.
Score scoreAnswer(const Question& question, const Answer& answer);

}  // namespace tlab::tasks
