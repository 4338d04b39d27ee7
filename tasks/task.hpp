#pragma once
// A task (Carnecky Sec. 8.1, Elmqvist Sec. 4): one module per task with one interface — probe
// selection by explicit, seeded rules with exact ground truth, and a pure score function.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/scene/camera.hpp"
#include "renderer/scene/scene.hpp"
#include "tasks/answer.hpp"
#include "tasks/question.hpp"
#include "tasks/score.hpp"
#include "tasks/task_settings.hpp"

namespace tlab::tasks {

// What probe() needs: the scene, the view the stimulus is rendered with, and the choice.
// Questions are produced one after the other from one seeded random stream, so the first K
// questions for `count` = N ≥ K are the same as for `count` = K (question K is reproducible).
struct ProbeRequest {
  const render::Scene& scene;
  render::Camera camera;
  int width = 512;
  int height = 512;
  int count = 1;
  std::uint64_t seed = 1;
  TaskSettings settings;
};

class Task {
 public:
  virtual ~Task() = default;
  virtual std::string name() const = 0;
  virtual std::string summary() const = 0;
  // The task's settings, including commonSettings().
  virtual std::vector<SettingSpec> settingSpecs() const = 0;
  // Exactly request.count questions, or throws std::runtime_error saying why no more could be found.
  virtual std::vector<Question> probe(const ProbeRequest& request) const = 0;
  // Pure: the same question and answer always give the same score.
  virtual Score score(const Question& question, const Answer& answer) const;

  TaskSettings settings(const std::vector<std::string>& assignments) const {
    return TaskSettings(name(), settingSpecs(), assignments);
  }
};

}  // namespace tlab::tasks
