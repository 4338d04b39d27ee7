#include "tasks/scoring.hpp"

#include <gtest/gtest.h>

#include "tasks/answer_parser.hpp"

namespace tlab::tasks {
namespace {

Question question(AnswerKind kind, GroundTruth truth, std::vector<std::string> labels = {}) {
  Question q;
  q.task = "test";
  q.answerKind = kind;
  q.truth = std::move(truth);
  q.timeLimitSeconds = 120.0;
  for (const auto& l : labels) q.points.push_back({l, kind == AnswerKind::Label ? "candidate" : "mark", {}, {}, -1});
  return q;
}

TEST(Scoring, JaccardIndexOfLabelSets) {
  EXPECT_DOUBLE_EQ(jaccardIndex({}, {}), 1.0);
  EXPECT_DOUBLE_EQ(jaccardIndex({"C"}, {}), 0.0);
  EXPECT_DOUBLE_EQ(jaccardIndex({"C", "D"}, {"C", "D"}), 1.0);
  EXPECT_DOUBLE_EQ(jaccardIndex({"C", "D"}, {"D", "E"}), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(jaccardIndex({"C"}, {"C", "D", "E", "F"}), 0.25);
}

TEST(Scoring, RelativeErrorOfCounts) {
  EXPECT_DOUBLE_EQ(relativeError(10, 10), 0.0);
  EXPECT_DOUBLE_EQ(relativeError(8, 10), 0.2);
  EXPECT_DOUBLE_EQ(relativeError(13, 10), 0.3);
  EXPECT_DOUBLE_EQ(relativeError(0, 4), 1.0);
  EXPECT_THROW(relativeError(1, 0), std::invalid_argument);
}

TEST(Scoring, ElmqvistTotalsOverTrials) {
  // Trials (answer, truth): errors 2, 3, 0 over 10 + 20 + 5 targets.
  const std::vector<CountingTrial> trials = {{8, 10}, {23, 20}, {5, 5}};
  EXPECT_DOUBLE_EQ(sumOfErrorsOverSumOfTargets(trials), 5.0 / 35.0);
  // Sums: answers 36, targets 35: the over- and under-count cancel to 1.
  EXPECT_DOUBLE_EQ(errorOfSumsOverSumOfTargets(trials), 1.0 / 35.0);
  EXPECT_THROW(sumOfErrorsOverSumOfTargets({}), std::invalid_argument);
}

TEST(Scoring, ErrorDistanceOnTheFloorPlan) {
  EXPECT_DOUBLE_EQ(errorDistance({1.0, 2.0}, {4.0, 6.0}), 5.0);
  EXPECT_DOUBLE_EQ(errorDistance({-1.0, -1.0}, {-1.0, -1.0}), 0.0);
}

TEST(Scoring, LayerNumberCorrectOrWrong) {
  const Question q = question(AnswerKind::LayerNumber, std::int64_t(3));
  const Score right = scoreAnswer(q, {"3", 10.0});
  EXPECT_TRUE(right.answered);
  EXPECT_TRUE(right.correct);
  EXPECT_EQ(right.value, 1.0);
  EXPECT_EQ(right.rawAnswer, "3");
  const Score wrong = scoreAnswer(q, {"2", 10.0});
  EXPECT_FALSE(wrong.correct);
  EXPECT_EQ(wrong.value, 0.0);
}

TEST(Scoring, MissingAnswerIsWrong) {
  const Question q = question(AnswerKind::LayerNumber, std::int64_t(3));
  const Score s = scoreAnswer(q, {std::nullopt, std::nullopt});
  EXPECT_FALSE(s.answered);
  EXPECT_FALSE(s.correct);
  EXPECT_EQ(s.value, 0.0);
  EXPECT_EQ(s.note, "missing");
}

TEST(Scoring, AnswerOverTheTimeLimitCountsAsMissing) {
  Question q = question(AnswerKind::LayerNumber, std::int64_t(3));
  q.timeLimitSeconds = 30.0;
  EXPECT_TRUE(scoreAnswer(q, {"3", 30.0}).correct);
  const Score late = scoreAnswer(q, {"3", 30.5});
  EXPECT_FALSE(late.answered);
  EXPECT_FALSE(late.correct);
  EXPECT_EQ(late.value, 0.0);
  EXPECT_EQ(late.rawAnswer, "3");
  EXPECT_EQ(late.note, "over the time limit");
}

TEST(Scoring, LabelSetExactMatchAndPartialCredit) {
  const Question q = question(AnswerKind::LabelSet, std::set<std::string>{"C", "E"}, {"A", "B", "C", "D", "E", "F"});
  const Score exact = scoreAnswer(q, {"E, C", std::nullopt});
  EXPECT_TRUE(exact.correct);
  EXPECT_DOUBLE_EQ(*exact.partialCredit, 1.0);
  const Score partial = scoreAnswer(q, {"C,D", std::nullopt});
  EXPECT_FALSE(partial.correct);
  EXPECT_EQ(partial.value, 0.0);
  EXPECT_DOUBLE_EQ(*partial.partialCredit, 1.0 / 3.0);
  const Question none = question(AnswerKind::LabelSet, std::set<std::string>{}, {"A", "B", "C"});
  EXPECT_TRUE(scoreAnswer(none, {"none", std::nullopt}).correct);
  EXPECT_FALSE(scoreAnswer(none, {"C", std::nullopt}).correct);
  EXPECT_DOUBLE_EQ(*scoreAnswer(q, {std::nullopt, std::nullopt}).partialCredit, 0.0);
}

TEST(Scoring, CountReportsRelativeError) {
  const Question q = question(AnswerKind::Count, std::int64_t(8));
  const Score s = scoreAnswer(q, {"6", std::nullopt});
  EXPECT_FALSE(s.correct);
  EXPECT_DOUBLE_EQ(*s.error, 0.25);
  EXPECT_TRUE(scoreAnswer(q, {"8", std::nullopt}).correct);
  // A missing count is scored as counting nothing: relative error 1.
  EXPECT_DOUBLE_EQ(*scoreAnswer(q, {std::nullopt, std::nullopt}).error, 1.0);
}

TEST(Scoring, FloorPointReportsErrorDistance) {
  Question q = question(AnswerKind::FloorPoint, glm::dvec2(2.0, -1.0));
  q.correctWithin = 0.5;
  const Score near = scoreAnswer(q, {"2.3,-1.4", std::nullopt});
  EXPECT_NEAR(*near.error, 0.5, 1e-12);
  EXPECT_TRUE(near.correct);
  const Score far = scoreAnswer(q, {"5,3", std::nullopt});
  EXPECT_DOUBLE_EQ(*far.error, 5.0);
  EXPECT_FALSE(far.correct);
}

TEST(Scoring, LetterAndLabel) {
  EXPECT_TRUE(scoreAnswer(question(AnswerKind::Letter, std::string("K")), {"k", std::nullopt}).correct);
  EXPECT_FALSE(scoreAnswer(question(AnswerKind::Letter, std::string("K")), {"R", std::nullopt}).correct);
  const Question q = question(AnswerKind::Label, std::string("Y"), {"X", "Y", "Z"});
  EXPECT_TRUE(scoreAnswer(q, {"Y", std::nullopt}).correct);
  EXPECT_FALSE(scoreAnswer(q, {"X", std::nullopt}).correct);
}

TEST(Scoring, MalformedAnswerThrows) {
  EXPECT_THROW(scoreAnswer(question(AnswerKind::LayerNumber, std::int64_t(1)), {"first", std::nullopt}), AnswerFormatError);
}

}  // namespace
}  // namespace tlab::tasks
