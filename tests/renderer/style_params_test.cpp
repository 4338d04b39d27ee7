#include <gtest/gtest.h>

#include "renderer/styles/style.hpp"

using namespace tlab::render;

TEST(StyleParams, DefaultsAndGivenValues) {
  const Style& constant = findStyle("constant");
  const StyleParams d = constant.resolve({});
  EXPECT_DOUBLE_EQ(d.number("alpha"), 0.25);
  EXPECT_TRUE(d.is("lighting", "headlight"));
  const StyleParams g = constant.resolve({{"alpha", "0.5"}, {"lighting", "none"}});
  EXPECT_DOUBLE_EQ(g.number("alpha"), 0.5);
  EXPECT_TRUE(g.is("lighting", "none"));
}

TEST(StyleParams, BadSettingsNameTheStyleAndKey) {
  const Style& constant = findStyle("constant");
  const auto message = [&](std::map<std::string, std::string> s) {
    try {
      constant.resolve(s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({{"beta", "1"}}).find("no parameter 'beta'"), std::string::npos);
  EXPECT_NE(message({{"alpha", "x"}}).find("'x' is not a number"), std::string::npos);
  EXPECT_NE(message({{"alpha", "1.5"}}).find("outside [0, 1]"), std::string::npos);
  EXPECT_NE(message({{"lighting", "sun"}}).find("not one of headlight, pbr, none"), std::string::npos);
  std::map<std::string, std::string> m;
  EXPECT_THROW(addSetting(m, "alpha"), std::invalid_argument);
  EXPECT_THROW(findStyle("watercolour"), std::invalid_argument);
}
