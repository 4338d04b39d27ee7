#include "study/window/answer_band.hpp"

#include <algorithm>

#include "study/window/window_style.hpp"

namespace tlab::study {

AnswerBand layoutAnswerBand(TextPainter& painter, std::string_view hint, std::string_view live, bool buttons, int width,
                            int minHeight) {
  AnswerBand b;
  b.textWidth = std::max(1, width - 2 * kAnswerMargin);
  b.hintLines = painter.wrapLines(hint, b.textWidth, kHintPixels);
  if (!live.empty()) b.liveLines = painter.wrapLines(live, b.textWidth, kLiveHintPixels);
  b.hintTop = kAnswerPad;
  b.liveTop = b.hintTop + int(b.hintLines.size()) * painter.lineHeight(kHintPixels);
  b.answerTop = b.liveTop + int(b.liveLines.size()) * painter.lineHeight(kLiveHintPixels) + kAnswerPad;
  b.refusalTop = b.answerTop + painter.lineHeight(kAnswerPixels);
  const int textBottom = b.refusalTop + kRefusalLines * painter.lineHeight(kRefusalPixels) + kAnswerPad;
  b.height = std::max(minHeight, textBottom + (buttons ? kButtonRowHeight : 0));
  return b;
}

std::vector<std::string> refusalLines(TextPainter& painter, std::string_view refusal, const AnswerBand& band) {
  std::vector<std::string> lines = painter.wrapLines(refusal, band.textWidth, kRefusalPixels);
  if (lines.size() <= std::size_t(kRefusalLines)) return lines;
  lines.resize(kRefusalLines);
  std::string& last = lines.back();
  const std::string ellipsis = "…";
  // Whole characters come off the end until the line and its ellipsis fit.
  while (!last.empty() && painter.lineWidth(last + ellipsis, kRefusalPixels) > band.textWidth) dropLastCodepoint(last);
  last += ellipsis;
  return lines;
}

}  // namespace tlab::study
