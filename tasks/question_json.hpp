#pragma once
// JSON for questions and scores: what `tlab task probe --json` prints and what the stimuli and
// study libraries store next to each trial.
#include <nlohmann/json.hpp>

#include "tasks/question.hpp"
#include "tasks/score.hpp"

namespace tlab::tasks {

nlohmann::json groundTruthJson(const GroundTruth& truth);
nlohmann::json toJson(const Question& question);
nlohmann::json toJson(const Score& score);

}  // namespace tlab::tasks
