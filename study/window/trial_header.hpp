#pragma once
// The header band of the window's trial screen: the question on the left, word-wrapped so that it
// never runs under the trial counter ("Trial 3 of 24", right-aligned before the countdown) however
// long a translation is or however narrow the window, and the band as tall as the question needs.
#include <string>
#include <string_view>
#include <vector>

#include "study/run/text_painter.hpp"

namespace tlab::study {

constexpr float kQuestionPixels = 22.0f, kCounterPixels = 18.0f, kCountdownPixels = 24.0f;
constexpr int kHeaderMargin = 16, kHeaderTop = 12;
constexpr int kCountdownReserve = 100;  // the countdown ("m:ss") starts this far from the right edge

struct TrialHeader {
  std::vector<std::string> questionLines;  // drawn from (kHeaderMargin, kHeaderTop) down
  int questionWidth = 0;                   // the width they were wrapped to
  int counterX = 0;                        // where the counter starts
  int height = 0;                          // the band's height: at least `minHeight`, and every line fits
};

TrialHeader layoutTrialHeader(TextPainter& painter, std::string_view question, std::string_view counter, int width,
                              int minHeight);

}  // namespace tlab::study
