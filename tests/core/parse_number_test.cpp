// Numbers read from user text, and numbers written as text that reads back as the same number.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <sstream>

#include "core/parse_number.hpp"

using tlab::core::parseFiniteNumber;
using tlab::core::roundTripText;

TEST(ParseNumber, TheWholeTextIsOneFiniteNumber) {
  EXPECT_EQ(parseFiniteNumber("0.25"), 0.25);
  EXPECT_EQ(parseFiniteNumber("-1e3"), -1000.0);
  EXPECT_FALSE(parseFiniteNumber(""));
  EXPECT_FALSE(parseFiniteNumber("1x"));
  EXPECT_FALSE(parseFiniteNumber("nan"));
  EXPECT_FALSE(parseFiniteNumber("inf"));
  EXPECT_FALSE(parseFiniteNumber("1e999"));
}

// Where six significant digits are exact, the text is what an ostream writes (so messages and
// listings of the usual values read as before); where they are not, the digits that are needed.
TEST(ParseNumber, RoundTripTextKeepsEveryDigitAValueNeeds) {
  for (const double v : {0.0, 0.25, 1.0, 32.0, 100000.0, 1e6, 1e-6, 0.001, -2.5, 1e300}) {
    std::ostringstream os;
    os << v;
    EXPECT_EQ(roundTripText(v), os.str()) << v;
  }
  EXPECT_EQ(roundTripText(0.1234567), "0.1234567");
  EXPECT_EQ(roundTripText(0.1), "0.1");
  EXPECT_EQ(roundTripText(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(roundTripText(2147483647.0), "2147483647");
  EXPECT_EQ(roundTripText(double(FLT_MAX)), "3.4028234663852886e+38");
  for (const double v : {0.1234567, 1.0 / 3.0, M_PI, 1e-300, -123456.789, 2147483647.0, double(FLT_MAX),
                         std::nextafter(1.0, 2.0)})
    EXPECT_EQ(parseFiniteNumber(roundTripText(v)), v) << roundTripText(v);
}
