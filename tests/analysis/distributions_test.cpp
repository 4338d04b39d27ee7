// Tail probabilities: expected values from R 4.2.2 (reference/reference_values.R, "extreme tails"),
// whose pnorm/pt/pchisq are accurate to full double precision in the far tails.
#include "analysis/distributions.hpp"

#include <iomanip>

#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;

TEST(Distributions, FarTailsDoNotUnderflow) {
  // R: pnorm(-37) = 5.72557122252458e-300
  EXPECT_TRUE(relativelyNear(normalLowerTail(-37.0), 5.72557122252458e-300, 1e-12));
  EXPECT_TRUE(relativelyNear(normalUpperTail(37.0), 5.72557122252458e-300, 1e-12));
  // R: pt(-1e10, 30) = 1.03645346525618e-279
  EXPECT_TRUE(relativelyNear(studentTLowerTail(-1e10, 30), 1.03645346525618e-279, 1e-10));
  EXPECT_TRUE(relativelyNear(studentTUpperTail(1e10, 30), 1.03645346525618e-279, 1e-10));
  // R: 2 * pt(-200, 50) = 2 * 1.44112502327868e-74
  EXPECT_TRUE(relativelyNear(studentTPValue(-200, 50, Alternative::TwoSided), 2 * 1.44112502327868e-74, 1e-10));
  // R: pchisq(1300, 2, lower.tail = FALSE) = 5.11195194865116e-283 (= exp(-650) exactly)
  EXPECT_TRUE(relativelyNear(chiSquaredUpperTail(1300, 2), 5.11195194865116e-283, 1e-12));
  // About 1e-300, each distribution (R: pt(-5e10, 30) = 1.11288343427529e-300,
  // pchisq(1380, 1, lower.tail = FALSE) = 4.66115845567407e-302,
  // pf(1e30, 2, 20, lower.tail = FALSE) = 1.00000000000003e-290).
  EXPECT_TRUE(relativelyNear(studentTPValue(-5e10, 30, Alternative::Less), 1.11288343427529e-300, 1e-10));
  EXPECT_TRUE(relativelyNear(chiSquaredUpperTail(1380, 1), 4.66115845567407e-302, 1e-10));
  EXPECT_TRUE(relativelyNear(fisherFUpperTail(1e30, 2, 20), 1.00000000000003e-290, 1e-10));
  // F far tail below 1e-300 is still positive (R: 1.27629532665222e-316, a subnormal).
  EXPECT_GT(fisherFUpperTail(5000, 3, 400), 0.0);
  EXPECT_LT(fisherFUpperTail(5000, 3, 400), 1e-310);
}

TEST(Distributions, AlternativesAndLimits) {
  // Symmetry of t: P(T > t) = P(T < -t); the three alternatives partition correctly.
  const double t = 1.7;
  EXPECT_DOUBLE_EQ(studentTPValue(t, 12, Alternative::Greater), studentTLowerTail(-t, 12));
  EXPECT_NEAR(studentTPValue(t, 12, Alternative::Less) + studentTPValue(t, 12, Alternative::Greater), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(studentTPValue(-t, 12, Alternative::TwoSided), 2 * studentTUpperTail(t, 12));
  EXPECT_EQ(studentTPValue(std::numeric_limits<double>::infinity(), 5, Alternative::TwoSided), 0.0);
  EXPECT_EQ(fisherFUpperTail(0.0, 2, 10), 1.0);
  // Student t quantile: qt(0.975, 9) = 2.2621571627982049 (R).
  EXPECT_TRUE(relativelyNear(studentTQuantile(0.975, 9), 2.2621571627982049, 1e-13));
  EXPECT_THROW(studentTUpperTail(1.0, 0.0), AnalysisError);
  EXPECT_EQ(parseAlternative("two.sided"), Alternative::TwoSided);
  EXPECT_THROW(parseAlternative("sideways"), AnalysisError);
}

}  // namespace
}  // namespace tlab::analysis
