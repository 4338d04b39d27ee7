#include "tasks/letter_patterns.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/seeded_random.hpp"

namespace tlab::tasks {
namespace {

TEST(LetterPatterns, BitmapsAreFiveBySevenWithTheExpectedStrokes) {
  for (const char letter : patternLetters()) {
    const auto& bitmap = letterBitmap(letter);
    for (const auto& row : bitmap) {
      EXPECT_EQ(row.size(), 5u) << letter;
      EXPECT_EQ(row.find_first_not_of(".#"), std::string::npos) << letter;
    }
  }
  EXPECT_EQ(letterCells('C').size(), 13u);
  EXPECT_EQ(letterCells('K').size(), 14u);
  EXPECT_EQ(letterCells('R').size(), 18u);
  EXPECT_EQ(letterCells('X').size(), 13u);
  EXPECT_EQ(letterCells('Y').size(), 10u);
  // Y: the two arms meet in the middle column of row 3 and the stem goes down column 2.
  EXPECT_EQ(letterBitmap('Y')[3], "..#..");
  EXPECT_EQ(letterBitmap('Y')[6], "..#..");
  // C is open on the right; R closes its bowl on row 3.
  EXPECT_EQ(letterBitmap('C')[3], "#....");
  EXPECT_EQ(letterBitmap('R')[3], "####.");
  EXPECT_THROW(letterBitmap('Q'), std::invalid_argument);
}

TEST(LetterPatterns, EachLetterMatchesOnlyItselfUnderRotationScaleAndTranslation) {
  core::SeededRandom random(11);
  for (const char letter : patternLetters())
    for (int trial = 0; trial < 8; ++trial) {
      const double angle = random.uniform(0.0f, 6.2831853f);
      auto points = letterFloorPositions(letter, {random.uniform(-20.0f, 20.0f), random.uniform(-20.0f, 20.0f)},
                                         random.uniform(0.5f, 3.0f), angle);
      std::reverse(points.begin(), points.end());  // order must not matter
      EXPECT_EQ(matchingLetters(points), std::vector<char>{letter}) << letter << " at angle " << angle;
    }
}

TEST(LetterPatterns, SmallPlacementNoiseIsToleratedLargeIsNot) {
  auto points = letterFloorPositions('K', {1.0, 2.0}, 2.0, 0.4);
  points[3] += glm::dvec2(0.3, -0.2);  // 0.18 cells
  EXPECT_EQ(matchingLetters(points), std::vector<char>{'K'});
  points[3] += glm::dvec2(1.5, 0.0);  // almost a cell off
  EXPECT_TRUE(matchingLetters(points).empty());
}

TEST(LetterPatterns, MirroredLetterIsNotALetter) {
  // R mirrored left-right cannot be rotated onto R (rotation about the vertical axis keeps handedness).
  auto points = letterFloorPositions('R', {0.0, 0.0}, 1.0, 0.0);
  for (auto& p : points) p.x = -p.x;
  EXPECT_TRUE(matchingLetters(points).empty());
}

TEST(LetterPatterns, TooFewOrTooManyPointsMatchNothing) {
  auto points = letterFloorPositions('Y', {0.0, 0.0}, 1.0, 0.0);
  points.pop_back();
  EXPECT_TRUE(matchingLetters(points).empty());
  EXPECT_TRUE(matchingLetters({}).empty());
}

}  // namespace
}  // namespace tlab::tasks
