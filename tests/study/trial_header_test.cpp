// The window's trial header: a question of any length wraps left of the trial counter, which
// stays right-aligned before the countdown, and the band grows to hold every line (a long
// translation on a narrow window used to run under the counter).
#include <gtest/gtest.h>

#include <sstream>

#include "study/window/screen_layout.hpp"
#include "tests/support/wrapped_lines.hpp"
#include "study/window/trial_header.hpp"

using namespace tlab::study;

using tlab::testing::joinedWithSpaces;

TEST(TrialHeader, AShortQuestionTakesOneLineAndTheUsualBand) {
  TextPainter painter;
  const TrialHeader h = layoutTrialHeader(painter, "Which label is nearer?", "Trial 3 of 24", 1024, 64);
  ASSERT_EQ(h.questionLines.size(), 1u);
  EXPECT_EQ(h.questionLines[0], "Which label is nearer?");
  EXPECT_EQ(h.height, 64);
  // The counter ends a margin before the countdown.
  EXPECT_EQ(h.counterX + painter.lineWidth("Trial 3 of 24", kCounterPixels), 1024 - kCountdownReserve - kHeaderMargin);
}

TEST(TrialHeader, ALongQuestionWrapsLeftOfTheCounterAndTheBandHoldsEveryLine) {
  TextPainter painter;
  const std::string question =
      "Welche der beiden markierten Stellen auf der transparenten Oberfläche liegt näher an Ihnen, "
      "wenn Sie das Objekt von vorne betrachten?";
  const std::string counter = "Übungsdurchgang 3 von 24";
  const TrialHeader h = layoutTrialHeader(painter, question, counter, 640, 53);
  EXPECT_GT(h.questionLines.size(), 2u);
  EXPECT_EQ(joinedWithSpaces(h.questionLines), question);  // every word, in order
  for (const auto& line : h.questionLines) {
    EXPECT_LE(painter.lineWidth(line, kQuestionPixels), h.questionWidth) << line;
    EXPECT_LE(kHeaderMargin + painter.lineWidth(line, kQuestionPixels), h.counterX - kHeaderMargin) << line;
  }
  EXPECT_EQ(h.counterX + painter.lineWidth(counter, kCounterPixels), 640 - kCountdownReserve - kHeaderMargin);
  EXPECT_EQ(h.height, kHeaderTop + int(h.questionLines.size()) * painter.lineHeight(kQuestionPixels) + kHeaderTop);
  // The screen below starts under the taller band.
  const ScreenLayout l = makeScreenLayout(640, 480, 160, 160, h.height);
  EXPECT_EQ(l.header.height, h.height);
  EXPECT_GE(l.stimulus.y, h.height);
  EXPECT_LE(l.stimulus.y + l.stimulus.height, l.answer.y);
  EXPECT_EQ(makeScreenLayout(640, 480, 160, 160).header.height, defaultHeaderHeight(480));
}
