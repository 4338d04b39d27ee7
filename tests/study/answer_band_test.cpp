// The window's answer band: how to answer, how to move (live trials), the typed answer, a
// refusal and the buttons each get rows of their own, word-wrapped to the window, and the band
// grows to hold them (the typed answer used to be drawn over a live trial's hint, a refusal over
// the letter buttons, and a German hint ran off a 1024-pixel window).
#include <gtest/gtest.h>

#include "study/design/participant_texts.hpp"
#include "study/window/answer_band.hpp"
#include "study/window/screen_layout.hpp"
#include "tests/support/wrapped_lines.hpp"

using namespace tlab::study;

namespace {

using tlab::testing::joinedWithSpaces;

// Every line fits the band's text width.
void expectFits(TextPainter& painter, const std::vector<std::string>& lines, float pixels, const AnswerBand& b) {
  for (const auto& line : lines) EXPECT_LE(painter.lineWidth(line, pixels), b.textWidth) << line;
}

}  // namespace

TEST(AnswerBand, ShortHintsKeepTheUsualBandAndEachRowStartsBelowTheLast) {
  TextPainter painter;
  const ParticipantTexts en;
  const AnswerBand b = layoutAnswerBand(painter, en.text("window_answer.count"), "", false, 1024, defaultAnswerHeight(1000));
  ASSERT_EQ(b.hintLines.size(), 1u);
  EXPECT_TRUE(b.liveLines.empty());
  EXPECT_EQ(b.height, defaultAnswerHeight(1000));
  EXPECT_EQ(b.hintTop, kAnswerPad);
  EXPECT_EQ(b.liveTop, b.hintTop + painter.lineHeight(kHintPixels));
  EXPECT_EQ(b.answerTop, b.liveTop + kAnswerPad);
  EXPECT_EQ(b.refusalTop, b.answerTop + painter.lineHeight(kAnswerPixels));
  EXPECT_LE(b.refusalTop + kRefusalLines * painter.lineHeight(kRefusalPixels) + kAnswerPad, b.height);
  EXPECT_EQ(b.textWidth, 1024 - 2 * kAnswerMargin);
}

TEST(AnswerBand, AGermanLiveTrialWrapsBothHintsAndTheAnswerRowStartsBelowThem) {
  TextPainter painter;
  const ParticipantTexts de("de");
  const std::string hint = de.text("window_answer.direction"), live = de.text("live.orbit");
  const AnswerBand b = layoutAnswerBand(painter, hint, live, false, 640, defaultAnswerHeight(480));
  EXPECT_GE(b.hintLines.size(), 2u);
  EXPECT_GE(b.liveLines.size(), 2u);
  EXPECT_EQ(joinedWithSpaces(b.hintLines), hint);  // every word, in order
  EXPECT_EQ(joinedWithSpaces(b.liveLines), live);
  expectFits(painter, b.hintLines, kHintPixels, b);
  expectFits(painter, b.liveLines, kLiveHintPixels, b);
  EXPECT_EQ(b.liveTop, b.hintTop + int(b.hintLines.size()) * painter.lineHeight(kHintPixels));
  EXPECT_EQ(b.answerTop, b.liveTop + int(b.liveLines.size()) * painter.lineHeight(kLiveHintPixels) + kAnswerPad);
  EXPECT_EQ(b.height, b.refusalTop + kRefusalLines * painter.lineHeight(kRefusalPixels) + kAnswerPad);
  EXPECT_GT(b.height, defaultAnswerHeight(480));
  // The screen above ends where the taller band begins.
  const ScreenLayout l = makeScreenLayout(640, 480, 160, 160, 0, b.height);
  EXPECT_EQ(l.answer.height, b.height);
  EXPECT_EQ(l.answer.y, 480 - b.height);
  EXPECT_LE(l.stimulus.y + l.stimulus.height, l.answer.y);
  EXPECT_EQ(makeScreenLayout(640, 480, 160, 160).answer.height, defaultAnswerHeight(480));
}

TEST(AnswerBand, ButtonsSitBelowTheRefusalsRoom) {
  TextPainter painter;
  const ParticipantTexts en;
  const AnswerBand b = layoutAnswerBand(painter, en.text("window_answer.letter"), "", true, 640, defaultAnswerHeight(480));
  const int textBottom = b.refusalTop + kRefusalLines * painter.lineHeight(kRefusalPixels) + kAnswerPad;
  EXPECT_EQ(b.height, textBottom + kButtonRowHeight);
  // buttonRow puts the buttons at the band's bottom: they start below the refusal's room.
  const ScreenLayout l = makeScreenLayout(640, 480, 160, 160, 0, b.height);
  const std::vector<Button> buttons = buttonRow(l.answer, {"C", "K", "R", "X", "Y"});
  ASSERT_EQ(buttons.size(), 5u);
  for (const auto& button : buttons) {
    EXPECT_GE(button.rect.y, l.answer.y + textBottom) << button.label;
    EXPECT_LE(button.rect.y + button.rect.height, l.answer.y + l.answer.height) << button.label;
  }
}

TEST(AnswerBand, ARefusalTakesAtMostItsRoomAndALongerOneEndsInAnEllipsis) {
  TextPainter painter;
  const ParticipantTexts de("de");
  const AnswerBand b = layoutAnswerBand(painter, "x", "", false, 640, 0);
  const std::string shortRefusal = de.text("refusal.count");
  const std::vector<std::string> one = refusalLines(painter, shortRefusal, b);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], shortRefusal);
  std::string longRefusal;
  for (int i = 0; i < 6; ++i) longRefusal += de.text("trial.refused") + " ";
  const std::vector<std::string> cut = refusalLines(painter, longRefusal, b);
  ASSERT_EQ(cut.size(), std::size_t(kRefusalLines));
  expectFits(painter, cut, kRefusalPixels, b);
  EXPECT_EQ(cut.back().substr(cut.back().size() - std::string("…").size()), "…");
  EXPECT_EQ(longRefusal.rfind(cut[0], 0), 0u);  // the first line is the text's beginning
  EXPECT_TRUE(refusalLines(painter, "", b).empty() || joinedWithSpaces(refusalLines(painter, "", b)).empty());
}
