// statcheck's own decision-error cases (statcheck 1.6.0, tests/testthat/test-decisionerror.R),
// rewritten as GoogleTest tables. Conventions (R/decision_error_test.R): a decision error is an
// error whose reported p and the p recomputed from the printed statistic (a point, not the
// rounding range) fall on different sides of alpha; by default p = alpha counts as significant
// (pEqualAlphaSig = TRUE, our --p-equal-alpha-not-significant turns it off). A statistic reported
// with "<" or ">" bounds the p on one side, so some combinations can never be decision errors.
// The t values are the texts statcheck's tests paste: qt(.04/2, 28, lower.tail = FALSE) etc.,
// printed by R 4.2.2 with 15 significant digits.
#include <string>
#include <vector>

#include "analysis/statcheck.hpp"
#include "analysis/statcheck_scanner.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

// R: qt(.04/2, 28, lower.tail = FALSE) and neighbours, as.character().
const std::string t04 = "2.15393486769497", t05 = "2.04840714179524", t06 = "1.9601364678398";
const std::string t05p = "2.04850714179525", t05m = "2.04830714179524";    // t.05 ± .0001
const std::string t04m = "2.15293486769497", t04p3 = "2.15493486769497";   // t.04 ∓ .001
const std::string t05m3 = "2.04740714179525", t05p3 = "2.04940714179524";  // t.05 ∓ .001
const std::string t06m3 = "1.9591364678398", t06p3 = "1.9611364678398";    // t.06 ∓ .001

// -1: statcheck's test does not assert this case under that option.
struct Case {
  std::string statistic;  // "t(28) = " + value
  std::string p;          // "p = .04"
  int expected;           // decision error with statcheck's defaults
  int expectedNotSig;     // with pEqualAlphaSig = FALSE
};

bool decisionError(const std::string& text, const StatcheckOptions& options) {
  const std::vector<ApaResult> r = extractApaResults(text);
  EXPECT_EQ(r.size(), 1u) << text;
  return !r.empty() && checkApaResult(r[0], false, options).decisionError;
}

void expectCases(const std::vector<Case>& cases) {
  StatcheckOptions notSig;
  notSig.pEqualAlphaSignificant = false;
  for (const Case& c : cases) {
    const std::string text = c.statistic + ", " + c.p;
    if (c.expected >= 0) {
      EXPECT_EQ(decisionError(text, {}), c.expected == 1) << text;
    }
    if (c.expectedNotSig >= 0) {
      EXPECT_EQ(decisionError(text, notSig), c.expectedNotSig == 1) << text << " (p = alpha not significant)";
    }
  }
}

TEST(StatcheckDecision, SimpleDecisionErrorsOfEveryTestType) {
  for (const char* text : {"t(28) = 2.20, p = .06", "t(28) = 1.20, p = .03", "F(2, 28) = 22.20, p = .06",
                           "F(2, 28) = 2.20, p = .03", "r(28) = .22, p = .03", "r(28) = .52, p = .06",
                           "chi2(28) = 2.20, p = .03", "chi2(28) = 52.20, p = .06", " z = 1.20, p = .03",
                           " z = 2.20, p = .06", "Q(28) = 2.20, p = .03", "Q(28) = 52.20, p = .06"})
    EXPECT_TRUE(decisionError(text, {})) << text;
}

TEST(StatcheckDecision, AlphaIsAnOption) {
  const auto at = [](double alpha) {
    StatcheckOptions o;
    o.alpha = alpha;
    return o;
  };
  EXPECT_TRUE(decisionError("t(28) = 2.20, p = .06", at(.05)));
  EXPECT_TRUE(decisionError("t(28) = 1.20, p = .03", at(.05)));
  EXPECT_TRUE(decisionError("t(28) = 2.20, p = .11", at(.10)));
  EXPECT_TRUE(decisionError("t(28) = 1.20, p = .09", at(.10)));
  EXPECT_TRUE(decisionError("t(28) = 5.20, p = .02", at(.01)));
  EXPECT_TRUE(decisionError("t(28) = 1.20, p = .005", at(.01)));
}

TEST(StatcheckDecision, PEqualToAlphaIsSignificantUnlessToldOtherwise) {
  StatcheckOptions notSig;
  notSig.pEqualAlphaSignificant = false;
  StatcheckOptions ten;
  ten.alpha = .10;
  StatcheckOptions tenNotSig = notSig;
  tenNotSig.alpha = .10;
  EXPECT_FALSE(decisionError("t(28) = 2.20, p = .05", {}));
  EXPECT_TRUE(decisionError("t(28) = 2.20, p = .05", notSig));
  EXPECT_FALSE(decisionError("t(28) = 2.20, p = .10", ten));
  EXPECT_TRUE(decisionError("t(28) = 2.20, p = .10", tenNotSig));
}

TEST(StatcheckDecision, StatisticEqualPEqual) {
  const std::string s = "t(28) = ";
  expectCases({{s + t04, "p = .04", 0, 0}, {s + t05p, "p = .04", 0, -1}, {s + t05m, "p = .04", -1, 1},
               {s + t06, "p = .04", 1, 1}, {s + t04, "p = .05", 0, 1}, {s + t05, "p = .05", 0, 0},
               {s + t06, "p = .05", 1, 0}, {s + t04, "p = .06", 1, 1}, {s + t05p, "p = .06", 1, -1},
               {s + t05m, "p = .06", -1, 0}, {s + t06, "p = .06", 0, 0}});
}

TEST(StatcheckDecision, StatisticEqualPLess) {
  const std::string s = "t(28) = ";
  expectCases({{s + t04m, "p < .04", 0, 0}, {s + t05p, "p < .04", 0, -1}, {s + t05m, "p < .04", -1, 1},
               {s + t06, "p < .04", 1, 1}, {s + t04, "p < .05", 0, 0}, {s + t05p, "p < .0500", 0, -1},
               {s + t05m, "p < .0500", -1, 1}, {s + t06, "p < .05", 1, 1}, {s + t04, "p < .06", 0, 0},
               {s + t05p, "p < .06", 0, -1}, {s + t05m, "p < .06", -1, 0}, {s + t06, "p < .06", 0, 0}});
}

TEST(StatcheckDecision, StatisticEqualPGreater) {
  const std::string s = "t(28) = ";
  expectCases({{s + t04p3, "p > .04", 0, 0}, {s + t05p, "p > .04", 0, -1}, {s + t05m, "p > .04", -1, 0},
               {s + t06, "p > .04", 0, 0}, {s + t04, "p > .05", 1, 1}, {s + t05p, "p > .05", 1, -1},
               {s + t05m, "p > .05", -1, 0}, {s + t06, "p > .05", 0, 0}, {s + t04, "p > .06", 1, 1},
               {s + t05p, "p > .06", 1, -1}, {s + t05m, "p > .06", -1, 0}, {s + t06, "p > .06", 0, 0}});
}

TEST(StatcheckDecision, StatisticLessPEqual) {
  const std::string s = "t(28) < ";
  expectCases({{s + t04m, "p = .0400", 0, 0}, {s + t05m, "p = .04", 1, 1}, {s + t06, "p = .04", 1, 1},
               {s + t04, "p = .05", 0, 0}, {s + t05m3, "p = .0500", 1, 0}, {s + t06, "p = .05", 1, 0},
               {s + t04, "p = .06", 0, 0}, {s + t05m, "p = .0600", 0, 0}, {s + t06m3, "p = .0600", 0, 0}});
}

TEST(StatcheckDecision, StatisticLessPLess) {
  const std::string s = "t(28) < ";
  expectCases({{s + t04, "p < .04", 0, 0}, {s + t05m, "p < .04", 1, 1}, {s + t06, "p < .04", 1, 1},
               {s + t04, "p < .05", 0, 0}, {s + t05m, "p < .05", 1, 1}, {s + t06, "p < .05", 1, 1},
               {s + t04, "p < .06", 0, 0}, {s + t05m, "p < .06", 0, 0}, {s + t06, "p < .06", 0, 0}});
}

// "t < x, p > v" bounds p from below twice: never an error, never a decision error.
TEST(StatcheckDecision, StatisticLessPGreater) {
  const std::string s = "t(28) < ";
  expectCases({{s + t04, "p > .04", 0, 0}, {s + t05m, "p > .04", 0, 0}, {s + t06, "p > .04", 0, 0},
               {s + t04, "p > .05", 0, 0}, {s + t05m, "p > .05", 0, 0}, {s + t06, "p > .05", 0, 0},
               {s + t04, "p > .06", 0, 0}, {s + t05m, "p > .06", 0, 0}, {s + t06, "p > .06", 0, 0}});
}

TEST(StatcheckDecision, StatisticGreaterPEqual) {
  const std::string s = "t(28) > ";
  expectCases({{s + t04p3, "p = .0400", 0, 0}, {s + t05p, "p = .04", 0, 0}, {s + t06, "p = .04", 0, 0},
               {s + t04, "p = .05", 0, 1}, {s + t05p3, "p = .0500", 0, 1}, {s + t06, "p = .05", 0, 0},
               {s + t04, "p = .06", 1, 1}, {s + t05p3, "p = .0600", 1, 1}, {s + t06p3, "p = .0600", 0, 0}});
}

// "t > x, p < v" bounds p from above twice: never an error.
TEST(StatcheckDecision, StatisticGreaterPLess) {
  const std::string s = "t(28) > ";
  expectCases({{s + t04p3, "p < .0400", 0, 0}, {s + t05p, "p < .04", 0, 0}, {s + t06, "p < .04", 0, 0},
               {s + t04, "p < .05", 0, 0}, {s + t05p3, "p < .0500", 0, 0}, {s + t06, "p < .05", 0, 0},
               {s + t04, "p < .06", 0, 0}, {s + t05p3, "p < .0600", 0, 0}, {s + t06p3, "p < .0600", 0, 0}});
}

TEST(StatcheckDecision, StatisticGreaterPGreater) {
  const std::string s = "t(28) > ";
  expectCases({{s + t04p3, "p > .0400", 0, 0}, {s + t05p, "p > .04", 0, 0}, {s + t06, "p > .04", 0, 0},
               {s + t04, "p > .05", 1, 1}, {s + t05p3, "p > .0500", 1, 1}, {s + t06, "p > .05", 0, 0},
               {s + t04, "p > .06", 1, 1}, {s + t05p3, "p > .0600", 1, 1}, {s + t06p3, "p > .0600", 0, 0}});
}

}  // namespace
}  // namespace tlab::analysis
