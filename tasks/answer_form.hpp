#pragma once
// How a question is answered, in one place per answer kind (the jsPsych idea of a trial type as one
// package, for the answer): the one parser from the answer's text form, the text form of a value,
// the score, the words that tell a person how to answer, the widget a front end draws (as data), how
// a front end's input becomes the answer's text, and how a simulated observer and the load tester
// answer. Front ends (window, browser page, booklet, simulated observer, load tester) draw the few
// widget primitives of WidgetKind; nothing outside tasks/ switches on an AnswerKind.
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "core/seeded_random.hpp"
#include "tasks/answer.hpp"
#include "tasks/question.hpp"
#include "tasks/score.hpp"

namespace tlab::tasks {

// The input primitives every interactive front end implements once.
enum class WidgetKind {
  Number,          // a typed whole number in [minimum, maximum]
  PickLabel,       // click one of the marked points (or its button)
  PickLabels,      // click any number of the marked points, then Done ("none" when none)
  Buttons,         // click one of the buttons, or press its key
  FloorPlanPoint,  // click a place on the floor plan shown beside the stimulus
  Gauge,           // drag a gauge figure (a disk and its normal stick) until it lies on the surface
};
const char* widgetName(WidgetKind kind);  // "number", "pick-label", "pick-labels", "buttons", "floor-plan", "gauge"

// What a front end draws for a question. Pixel positions are in the stimulus image's pixels.
struct Widget {
  WidgetKind kind = WidgetKind::Number;
  std::int64_t minimum = 0, maximum = 1000000;  // Number
  std::vector<ProbePoint> marks;                // PickLabel, PickLabels: the points to click
  std::vector<std::string> buttons;             // Buttons: a key press of the one-letter label answers
  glm::dvec2 at{0.0};                           // Gauge: the probe's pixel position
  double radiusPixels = 0.0;                    // Gauge: the disk's radius in stimulus pixels
  double startSlant = 0.0, startTilt = 0.0;     // Gauge: the seeded start orientation, degrees
};

// What a participant did with a widget, before it is the answer's text.
struct TypedText { std::string text; };
struct PickedLabels { std::vector<std::string> labels; };  // one for PickLabel and Buttons
struct PlanPoint { glm::dvec2 world{0.0}; };               // world (x, z) of the floor-plan click
struct GaugeSetting { double slantDegrees = 0.0, tiltDegrees = 0.0; };
using WidgetInput = std::variant<TypedText, PickedLabels, PlanPoint, GaugeSetting>;

// The simulated observer's answer noise where an answer is a quantity (see SimulatedObserver).
struct AnswerNoise {
  double gaugeDegrees = 8.0;      // gauge figure: angular sd (degrees) of a seen normal, at visibility 1
  double gaugeGrowth = 3.0;       // ... times (1 + growth (1 − v)) at visibility v
};

class AnswerForm {
 public:
  virtual ~AnswerForm() = default;
  virtual AnswerKind kind() const = 0;
  virtual const char* name() const = 0;          // "layer-number", ...: stored with every trial
  virtual const char* format() const = 0;        // how to type it, for messages and --help
  virtual std::string hint() const = 0;          // how to answer, written for people
  // The one parser: the text form into the ground truth's alternative. Throws AnswerFormatError.
  virtual GroundTruth parse(const Question& q, const std::string& text) const = 0;
  // The answer's text form of a value of the ground truth's alternative (parse(text(v)) == v).
  virtual std::string text(const Question& q, const GroundTruth& value) const = 0;
  // Fills correct, value, partial credit and error of an answer parsed by parse().
  virtual void score(const Question& q, const GroundTruth& given, Score& s) const = 0;
  // A missing answer's error and partial credit, where the task defines them.
  virtual void scoreMissing(const Question&, Score&) const {}
  virtual Widget widget(const Question& q) const = 0;
  // The answer's text from a widget's input; throws AnswerFormatError for input the widget cannot give.
  virtual std::string fromInput(const Question& q, const WidgetInput& input) const;
  // The booklet's answer field ("answer (a layer number ...):"), or nullopt: cannot be printed.
  virtual std::optional<std::string> bookletField() const { return std::string(format()); }
  // A simulated observer that does not know: a guess among the possible answers.
  virtual std::string guess(const Question& q, core::SeededRandom& random) const = 0;
  // A simulated observer that knows, at visibility v: the truth, or a noisy estimate of a quantity.
  virtual std::string known(const Question& q, core::SeededRandom& random, double visibility, const AnswerNoise& noise) const;
  // Layers in front of what the question asks about (the observer's visibility falls with them).
  virtual int layersInFront(const Question&) const { return 0; }
};

// The form of a question's answer kind.
const AnswerForm& answerForm(AnswerKind kind);
inline const AnswerForm& answerForm(const Question& q) { return answerForm(q.answerKind); }

// A standard normal deviate (Box-Muller) from the portable uniform source; the simulated observer's.
double standardNormal(core::SeededRandom& random);
// "%.4f": how a measured quantity (a floor-plan point, a direction) is written in an answer.
std::string answerNumber(double v);

}  // namespace tlab::tasks
