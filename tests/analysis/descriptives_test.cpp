// Descriptives and outlier screening. Expected values: R 4.2.2 (mean, sd, quantile type 7,
// t-based CI) and exact rational arithmetic for the offset data (reference/offset_reference.py).
#include "analysis/descriptives.hpp"

#include "analysis/outliers.hpp"
#include "analysis/r_moments.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;
using testing::throwsWithMessage;

TEST(Descriptives, SleepGroupOne) {
  // R: x <- sleep$extra[1:10]; mean 0.75, sd 1.78900965775916, quantile(x) 25% -0.175, 50% 0.35,
  // 75% 1.7, t.test(x)$conf.int = -0.529780413526232 2.029780413526233.
  const std::vector<double> x = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
  const Descriptives d = describe(x, "group 1");
  EXPECT_EQ(d.n, 10u);
  EXPECT_TRUE(relativelyNear(d.mean, 0.75, 1e-14));
  EXPECT_TRUE(relativelyNear(d.sd, 1.78900965775916, 1e-13));
  EXPECT_TRUE(relativelyNear(d.variance, 1.78900965775916 * 1.78900965775916, 1e-13));
  EXPECT_TRUE(relativelyNear(d.se, 1.78900965775916 / std::sqrt(10.0), 1e-13));
  EXPECT_TRUE(relativelyNear(d.q1, -0.175, 1e-13));
  EXPECT_TRUE(relativelyNear(d.median, 0.35, 1e-13));
  EXPECT_TRUE(relativelyNear(d.q3, 1.7, 1e-13));
  EXPECT_TRUE(relativelyNear(d.ciLow, -0.529780413526232, 1e-12));
  EXPECT_TRUE(relativelyNear(d.ciHigh, 2.029780413526233, 1e-12));
}

TEST(Descriptives, OffsetByOneBillionKeepsTheSpread) {
  // Values 1e9 + 0.001·k; exact variance of these doubles (offset_reference.py):
  // 1.650005197717518967692740261554718017578125e-5; R: var(x) = 1.650005197717519e-05,
  // mean(x) - 1e9 = 4.999995231628418e-03. The one-pass formula Σx² - (Σx)²/n would
  // lose every digit here (Σx² ≈ 5e18, ulp 1024).
  std::vector<double> x;
  for (const int k : {1, 2, 4, 7, 11}) x.push_back(1e9 + 0.001 * k);
  const SampleSummary s = summarizeSample(x, "x");
  EXPECT_TRUE(relativelyNear(s.variance, 1.650005197717518967692740261554718017578125e-5, 1e-9));
  EXPECT_TRUE(relativelyNear(s.mean - 1e9, 0.00499999523162841796875, 1e-6));
}

TEST(Descriptives, NTwoAndTooFew) {
  // n = 2: var = (b - a)²/2, CI with t_{1}: qt(.975, 1) = 12.7062047361747 (R).
  const std::vector<double> two = {1.0, 4.0};
  const Descriptives d = describe(two, "pair");
  EXPECT_DOUBLE_EQ(d.variance, 4.5);
  EXPECT_TRUE(relativelyNear(d.ciHigh - d.mean, 12.7062047361747 * std::sqrt(4.5 / 2), 1e-12));
  const std::vector<double> one = {3.0};
  EXPECT_TRUE(throwsWithMessage([&] { describe(one, "cell group=a"); }, {"cell group=a", "n = 1", "at least 2"}));
}

TEST(Outliers, TukeyFencesAndZScoreAreReportedSeparately) {
  // 1..19 and 100: Q1 = 5.75, Q3 = 15.25 (type 7), upper fence 29.5 → 100 is a Tukey outlier;
  // its z = (100 - 14.5)/sd = 4.09941122770003 > 3 (R: x <- c(1:19, 100); (100 - mean(x))/sd(x)).
  std::vector<double> xs;
  for (int i = 1; i <= 19; ++i) xs.push_back(i);
  xs.push_back(100);
  const OutlierScreen s = screenOutliers(xs);
  EXPECT_DOUBLE_EQ(s.upperFence, 15.25 + 1.5 * 9.5);
  ASSERT_EQ(s.outliers.size(), 2u);
  EXPECT_EQ(s.outliers[0].rule, OutlierRule::TukeyFences);
  EXPECT_EQ(s.outliers[1].rule, OutlierRule::AbsoluteZAbove3);
  EXPECT_EQ(s.outliers[0].index, 19u);
  EXPECT_TRUE(relativelyNear(s.outliers[1].z, 4.09941122770003, 1e-13));
  const std::vector<double> clean = {1, 2, 3, 4, 5};
  EXPECT_TRUE(screenOutliers(clean).outliers.empty());
}

}  // namespace
}  // namespace tlab::analysis
