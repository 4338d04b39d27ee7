#pragma once
// A question of a task: its text, the marked points (3-D world position and 2-D pixel position),
// the exact ground truth, the kind of answer expected, the time limit, and the checks that made
// the question unique and unambiguous when it was chosen.
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

namespace tlab::tasks {

// What an answer is. The ground truth holds the matching alternative of GroundTruth.
enum class AnswerKind {
  LayerNumber,  // std::int64_t, 1 = front (Carnecky Task 1)
  LabelSet,     // std::set<std::string>, possibly empty (Carnecky Task 2)
  Label,        // std::string, one of the candidate labels (Carnecky Task 3)
  Count,        // std::int64_t >= 0 (Elmqvist T1, T4)
  FloorPoint,   // glm::dvec2 = world (x, z) on the floor plan (Elmqvist T3)
  Letter,       // std::string, one of C K R X Y (Elmqvist T2)
  Direction,    // glm::dvec3, a unit direction in world coordinates (the gauge figure's normal)
};
// Each kind's parser, text form, widget and simulated answer: tasks/answer_form.hpp.

const char* answerKindName(AnswerKind kind);
// How to type an answer of this kind, for messages and --help.
const char* answerFormat(AnswerKind kind);

using GroundTruth = std::variant<std::int64_t, std::string, std::set<std::string>, glm::dvec2, glm::dvec3>;

// A marked point. `pixel` is continuous: pixel (x, y) covers [x, x+1) × [y, y+1), row 0 = top,
// so the pixel containing the point is floor(pixel).
struct ProbePoint {
  std::string label;   // "A", "B", "X", ...
  std::string role;    // "probe", "start", "end", "mark", "given", "candidate", "target"
  glm::dvec3 world{0.0};
  glm::dvec2 pixel{0.0};
  int object = -1;     // index into Scene::objects, -1 if none
};

// A rule the question satisfied when it was chosen: `value` met `required` (see `rule`).
struct UniquenessCheck {
  std::string rule;
  double value = 0.0;
  double required = 0.0;
};

struct Question {
  std::string task;
  int number = 1;                 // 1-based, in the order probe() produced it
  std::string text;                // in English, as `tlab task probe` prints it
  // The same words as a key of the participant text table (study/design/texts/en.toml's [question])
  // with its {name} values: what front ends show participants, in the experiment's language.
  // Formatting the key's English text with textArgs gives `text` (a test checks every task).
  std::string textKey;
  std::map<std::string, std::string> textArgs;
  AnswerKind answerKind = AnswerKind::Label;
  std::vector<ProbePoint> points;
  GroundTruth truth;
  double timeLimitSeconds = 120.0;  // Carnecky Sec. 8: strictly limited time
  double correctWithin = 0.0;       // FloorPoint, Direction: the error counted as correct (distance, degrees)
  std::vector<UniquenessCheck> checks;
  std::vector<std::pair<std::string, double>> measurements;  // distances etc., for reports
  std::vector<std::pair<std::string, glm::dvec3>> directions;  // gauge figure: the view frame at the probe

  std::vector<std::string> labels() const;  // labels of the points, in order
};

}  // namespace tlab::tasks
