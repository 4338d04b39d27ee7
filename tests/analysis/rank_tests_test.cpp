// Rank tests. Expected values: R 4.2.2 wilcox.test / friedman.test (reference/reference_values.R).
#include "analysis/rank_tests.hpp"

#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;
using testing::throwsWithMessage;

constexpr double kDigits = 1e-10;

TEST(Wilcoxon, ExactWithoutTies) {
  // R: wilcox.test(x, y, paired = TRUE) (the depression data of R's ?wilcox.test): V = 40,
  // p = 0.0390625 (exact); greater: 0.01953125; less: 0.986328125.
  const std::vector<double> x = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
  const std::vector<double> y = {0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
  const auto r = wilcoxonSignedRankTest(x, y, 0.0, Alternative::TwoSided);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.V, 40.0);
  EXPECT_TRUE(relativelyNear(r.p, 0.0390625, 1e-14));
  EXPECT_TRUE(relativelyNear(wilcoxonSignedRankTest(x, y, 0.0, Alternative::Greater).p, 0.01953125, 1e-14));
  EXPECT_TRUE(relativelyNear(wilcoxonSignedRankTest(x, y, 0.0, Alternative::Less).p, 0.986328125, 1e-14));
}

TEST(Wilcoxon, TiesAndZerosUseTheCorrectedNormalApproximation) {
  // R: wilcox.test(tx, ty, paired = TRUE) with one zero difference and tied |d|: V = 35,
  // p = 0.0187153542058768 (normal approximation, tie and continuity corrections).
  const std::vector<double> x = {5, 7, 7, 9, 3, 4, 8, 8, 6, 2};
  const std::vector<double> y = {3, 5, 5, 9, 4, 1, 6, 5, 3, 2};
  const auto r = wilcoxonSignedRankTest(x, y, 0.0, Alternative::TwoSided);
  EXPECT_FALSE(r.exact);
  EXPECT_EQ(r.zeros, 2u);
  EXPECT_EQ(r.V, 35.0);
  EXPECT_TRUE(relativelyNear(r.p, 0.0187153542058768, kDigits));
  // R's sleep, paired: V = 0, p = 0.00909069801592506 (ties → normal approximation).
  const std::vector<double> s1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
  const std::vector<double> s2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
  const auto sleep = wilcoxonSignedRankTest(s1, s2, 0.0, Alternative::TwoSided);
  EXPECT_EQ(sleep.V, 0.0);
  EXPECT_TRUE(relativelyNear(sleep.p, 0.00909069801592506, kDigits));
}

TEST(Wilcoxon, ExactTailKeepsTinyProbabilities) {
  // R: psignrank(0, 40) = 9.09494701772928e-13 = 2^-40.
  EXPECT_TRUE(relativelyNear(signedRankLowerTail(0, 40), 9.09494701772928e-13, 1e-14));
  EXPECT_TRUE(relativelyNear(signedRankUpperTail(820, 40), 9.09494701772928e-13, 1e-14));
  EXPECT_TRUE(throwsWithMessage(
      [] {
        const std::vector<double> a = {1, 2};
        wilcoxonSignedRankTest(a, a, 0.0, Alternative::TwoSided);
      },
      {"all 2 differences are zero"}));
}

TEST(MannWhitney, ExactWithoutTies) {
  // R: wilcox.test(mx, my) (the ?wilcox.test permeability data): W = 35, p = 0.254412254412254;
  // greater: 0.127206127206127.
  const std::vector<double> x = {0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46};
  const std::vector<double> y = {1.15, 0.88, 0.90, 0.74, 1.21};
  const auto r = mannWhitneyTest(x, y, Alternative::TwoSided);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.W, 35.0);
  EXPECT_TRUE(relativelyNear(r.p, 0.254412254412254, kDigits));
  EXPECT_TRUE(relativelyNear(mannWhitneyTest(x, y, Alternative::Greater).p, 0.127206127206127, kDigits));
  // R: pwilcox(0, 45, 45) = 9.63136700882196e-27 = 1/choose(90, 45).
  EXPECT_TRUE(relativelyNear(rankSumLowerTail(0, 45, 45), 9.63136700882196e-27, 1e-12));
}

TEST(MannWhitney, TiesUseTheCorrectedNormalApproximation) {
  // R: wilcox.test(ux, uy): W = 7.5, p = 0.018422125454099; sleep: W = 25.5, p = 0.0693275754336266.
  const std::vector<double> x = {1, 2, 2, 3, 3, 3, 4, 5};
  const std::vector<double> y = {3, 4, 4, 5, 5, 6, 6};
  const auto r = mannWhitneyTest(x, y, Alternative::TwoSided);
  EXPECT_FALSE(r.exact);
  EXPECT_EQ(r.W, 7.5);
  EXPECT_TRUE(relativelyNear(r.p, 0.018422125454099, kDigits));
  const std::vector<double> s1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
  const std::vector<double> s2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
  const auto sleep = mannWhitneyTest(s1, s2, Alternative::TwoSided);
  EXPECT_EQ(sleep.W, 25.5);
  EXPECT_TRUE(relativelyNear(sleep.p, 0.0693275754336266, kDigits));
  const std::vector<double> same = {2, 2, 2};
  EXPECT_TRUE(throwsWithMessage([&] { mannWhitneyTest(same, same, Alternative::TwoSided); }, {"all 6 values are tied"}));
}

TEST(Friedman, RoundingTimesWithTies) {
  // R: friedman.test(RoundingTimes) (?friedman.test; Hollander & Wolfe 1973, p. 140):
  // chi-squared = 11.1428571428571, df = 2, p = 0.00380504077551136.
  const double data[22][3] = {{5.40, 5.50, 5.55}, {5.85, 5.70, 5.75}, {5.20, 5.60, 5.50}, {5.55, 5.50, 5.40},
                              {5.90, 5.85, 5.70}, {5.45, 5.55, 5.60}, {5.40, 5.40, 5.35}, {5.45, 5.50, 5.35},
                              {5.25, 5.15, 5.00}, {5.85, 5.80, 5.70}, {5.25, 5.20, 5.10}, {5.65, 5.55, 5.45},
                              {5.60, 5.35, 5.45}, {5.05, 5.00, 4.95}, {5.50, 5.50, 5.40}, {5.45, 5.55, 5.50},
                              {5.55, 5.55, 5.35}, {5.45, 5.50, 5.55}, {5.50, 5.45, 5.25}, {5.65, 5.60, 5.40},
                              {5.70, 5.65, 5.55}, {6.30, 6.30, 6.25}};
  Eigen::MatrixXd y(22, 3);
  for (int i = 0; i < 22; ++i)
    for (int j = 0; j < 3; ++j) y(i, j) = data[i][j];
  const FriedmanResult r = friedmanTest(y);
  EXPECT_TRUE(relativelyNear(r.chiSquared, 11.1428571428571, 1e-12));
  EXPECT_EQ(r.df, 2.0);
  EXPECT_TRUE(relativelyNear(r.p, 0.00380504077551136, kDigits));
  Eigen::MatrixXd flat = Eigen::MatrixXd::Ones(3, 2);
  EXPECT_TRUE(throwsWithMessage([&] { friedmanTest(flat); }, {"same value in all conditions"}));
}

}  // namespace
}  // namespace tlab::analysis
