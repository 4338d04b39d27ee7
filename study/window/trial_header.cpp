#include "study/window/trial_header.hpp"

#include <algorithm>

namespace tlab::study {

TrialHeader layoutTrialHeader(TextPainter& painter, std::string_view question, std::string_view counter, int width,
                              int minHeight) {
  TrialHeader h;
  const int countdownX = width - kCountdownReserve;
  h.counterX = std::max(kHeaderMargin, countdownX - kHeaderMargin - painter.lineWidth(counter, kCounterPixels));
  h.questionWidth = std::max(1, h.counterX - 2 * kHeaderMargin);
  h.questionLines = painter.wrapLines(question, h.questionWidth, kQuestionPixels);
  const int textHeight = int(h.questionLines.size()) * painter.lineHeight(kQuestionPixels);
  h.height = std::max(minHeight, kHeaderTop + textHeight + kHeaderTop);
  return h;
}

}  // namespace tlab::study
