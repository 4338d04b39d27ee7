#pragma once
// The answer band at the bottom of the window's trial screen, top to bottom: how to answer, how
// to move in a live trial, the typed answer (or the chosen labels), room for a refusal, and the
// widget's buttons — each in rows of its own, word-wrapped to the window, so that no line runs
// into another or off the screen however long a translation is or however narrow the window (the
// typed answer used to sit on the live trial's hint, and a German hint ran past 1024 pixels).
// The band is as tall as its rows need, and at least the usual height.
#include <string>
#include <string_view>
#include <vector>

#include "study/run/text_painter.hpp"

namespace tlab::study {

constexpr float kHintPixels = 18.0f, kLiveHintPixels = 16.0f, kAnswerPixels = 22.0f, kRefusalPixels = 16.0f;
constexpr int kAnswerMargin = 16;       // left and right
constexpr int kAnswerPad = 8;           // above the first row, between rows, below the last
constexpr int kRefusalLines = 2;        // a refusal's room: longer ones end in "…"
constexpr int kButtonRowHeight = 48 + 8;  // buttonRow's buttons and the gap under them

struct AnswerBand {
  std::vector<std::string> hintLines;      // how to answer
  std::vector<std::string> liveLines;      // how to move (live trials only)
  int textWidth = 0;                       // the width every line fits in
  // Offsets from the band's top of each row's first line.
  int hintTop = 0, liveTop = 0, answerTop = 0, refusalTop = 0;
  int height = 0;                          // the band's height: at least `minHeight`, and every row fits
};

// `live` empty: no live hint. `buttons`: the widget draws a row of buttons at the band's bottom.
AnswerBand layoutAnswerBand(TextPainter& painter, std::string_view hint, std::string_view live, bool buttons, int width,
                            int minHeight);

// A refusal as the band shows it: at most kRefusalLines lines of its width, the last cut short
// with "…" when the text needs more.
std::vector<std::string> refusalLines(TextPainter& painter, std::string_view refusal, const AnswerBand& band);

}  // namespace tlab::study
