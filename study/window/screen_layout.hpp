#pragma once
// ScreenLayout: where things go on a participant's screen of a given size — the header (question
// and countdown), the stimulus in the middle at its rendered size or a whole multiple of it, the answer band at the
// bottom with its buttons (letters, Likert points) — and the mapping between stimulus pixels and
// screen pixels used to draw the marks and to hit-test clicks on labels. Pure geometry.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "study/run/canvas.hpp"

namespace tlab::study {

struct Button {
  std::string label;
  Rect rect;
};

struct ScreenLayout {
  int width = 0, height = 0;
  Rect header;
  Rect stimulus;  // where the stimulus image is drawn
  Rect answer;    // the answer band
  std::optional<Rect> plan;  // the floor plan beside the stimulus (floor-point answers)
  int stimulusWidth = 0, stimulusHeight = 0;

  // Stimulus pixel (continuous, row 0 = top) → screen pixel, and back.
  glm::dvec2 toScreen(glm::dvec2 stimulusPixel) const;
  glm::dvec2 toStimulus(glm::dvec2 screenPixel) const;
};

// The header is max(48, height / 12) pixels tall, or `headerHeight` when that is more (a long
// question); the answer band max(96, height / 7), or `answerHeight` when that is more (long hints).
ScreenLayout makeScreenLayout(int width, int height, int stimulusWidth, int stimulusHeight, int headerHeight = 0,
                              int answerHeight = 0);
// The stimulus on the left, a floor plan of the same size on the right.
ScreenLayout makeScreenLayoutWithPlan(int width, int height, int stimulusWidth, int stimulusHeight, int headerHeight = 0,
                                      int answerHeight = 0);
// The header's and the answer band's heights without long texts.
int defaultHeaderHeight(int height);
int defaultAnswerHeight(int height);

// A row of equal buttons centred in `band`.
std::vector<Button> buttonRow(const Rect& band, const std::vector<std::string>& labels, int buttonWidth = 64, int gap = 12);

// The label whose screen position is within `radius` of `screen`, or -1 (nearest wins).
int hitPoint(const std::vector<glm::dvec2>& screenPoints, glm::dvec2 screen, double radius = 16.0);

}  // namespace tlab::study
