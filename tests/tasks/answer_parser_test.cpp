#include "tasks/answer_parser.hpp"

#include <gtest/gtest.h>

namespace tlab::tasks {
namespace {

// The message of the AnswerFormatError `f` throws.
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const AnswerFormatError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(AnswerParser, LayerNumber) {
  EXPECT_EQ(parseLayerNumber(" 3 "), 3);
  EXPECT_NE(errorOf([] { parseLayerNumber("0"); }).find("layer number"), std::string::npos);
  EXPECT_NE(errorOf([] { parseLayerNumber("2.5"); }).find("got '2.5'"), std::string::npos);
  EXPECT_NE(errorOf([] { parseLayerNumber(""); }).find("whole number"), std::string::npos);
}

TEST(AnswerParser, Count) {
  EXPECT_EQ(parseCount("0"), 0);
  EXPECT_EQ(parseCount("12"), 12);
  EXPECT_NE(errorOf([] { parseCount("-1"); }).find("a count"), std::string::npos);
  EXPECT_NE(errorOf([] { parseCount("twelve"); }).find("'twelve'"), std::string::npos);
}

TEST(AnswerParser, LabelSet) {
  const std::vector<std::string> labels = {"A", "B", "C", "D"};
  EXPECT_EQ(parseLabelSet("c, d", labels), (std::set<std::string>{"C", "D"}));
  EXPECT_EQ(parseLabelSet("C D", labels), (std::set<std::string>{"C", "D"}));
  EXPECT_TRUE(parseLabelSet("none", labels).empty());
  EXPECT_TRUE(parseLabelSet("", labels).empty());
  const std::string unknown = errorOf([&] { parseLabelSet("C,Q", labels); });
  EXPECT_NE(unknown.find("'Q'"), std::string::npos);
  EXPECT_NE(unknown.find("A, B, C, D"), std::string::npos);
  EXPECT_NE(errorOf([&] { parseLabelSet("C,C", labels); }).find("twice"), std::string::npos);
}

TEST(AnswerParser, Label) {
  const std::vector<std::string> labels = {"X", "Y", "Z"};
  EXPECT_EQ(parseLabel(" y", labels), "Y");
  EXPECT_NE(errorOf([&] { parseLabel("X,Y", labels); }).find("one label"), std::string::npos);
  EXPECT_NE(errorOf([&] { parseLabel("W", labels); }).find("X, Y, Z"), std::string::npos);
}

TEST(AnswerParser, FloorPoint) {
  EXPECT_EQ(parseFloorPoint("1.5, -2"), glm::dvec2(1.5, -2.0));
  EXPECT_NE(errorOf([] { parseFloorPoint("1.5"); }).find("'X,Z'"), std::string::npos);
  EXPECT_NE(errorOf([] { parseFloorPoint("1,2,3"); }).find("'X,Z'"), std::string::npos);
  EXPECT_NE(errorOf([] { parseFloorPoint("a,b"); }).find("got 'a,b'"), std::string::npos);
}

TEST(AnswerParser, Letter) {
  EXPECT_EQ(parseLetter("r"), "R");
  EXPECT_NE(errorOf([] { parseLetter("Q"); }).find("C, K, R, X, Y"), std::string::npos);
  EXPECT_NE(errorOf([] { parseLetter("CK"); }).find("'CK'"), std::string::npos);
}

}  // namespace
}  // namespace tlab::tasks
