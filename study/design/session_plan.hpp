#pragma once
// SessionPlan: the ordered list of everything one participant slot is asked — for every block of
// the slot's design row, training trials for a task the first time it appears, then the block's
// trials, each with its questions. A planned trial knows the stimulus it needs (scene, style,
// settings, camera, size) and the seed of its probe selection, so the plan is fully determined
// by the experiment file and the slot. One PlannedTrial is one record (one question, one answer).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/design/counterbalancing.hpp"
#include "study/design/experiment.hpp"

namespace tlab::study {

enum class Phase { Training, Test };
const char* phaseName(Phase phase);

struct StimulusKey {
  std::string scene;
  std::string style;
  std::string camera;
  std::vector<std::string> renderSettings;
  int width = 512;
  int height = 512;
  std::string images{};  // a PNG from another renderer shown instead of tlab's picture (Level::images), or empty
  std::string text() const;      // a stable one-line description (cache key)
  std::string viewText() const;  // the same without style and render settings: what the geometry depends on
};

struct PlannedTrial {
  int sequence = 0;  // 1-based position in the session
  Phase phase = Phase::Test;
  int block = 0;     // 1-based block of the design row
  std::string condition;                     // "method=alpha, scene=pretzel"
  std::map<std::string, std::string> levels;  // factor → level
  std::string taskId;
  std::string task;
  std::vector<std::string> taskSettings;
  int trial = 1;      // 1-based repetition within the block (training: within the training run)
  int question = 1;   // 1-based question within the trial
  int questionsInTrial = 1;
  StimulusKey stimulus;
  std::uint64_t probeSeed = 0;
  double timeLimitSeconds = 120.0;
  std::optional<double> trialTimeLimitSeconds;
  Navigation navigation = Navigation::None;  // interactive trial: live rendering in the window
};

struct SessionPlan {
  SlotDesign design;
  std::vector<PlannedTrial> trials;
};

SessionPlan makeSessionPlan(const Experiment& experiment, const Design& design, int slot);

}  // namespace tlab::study
