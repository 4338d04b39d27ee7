// t-tests. Expected values: R 4.2.2 t.test on the `sleep` data set (reference/reference_values.R),
// printed with 15 significant digits; the rounded values t = -4.0621 (paired, df 9) and
// t = -1.8608, df = 17.776 (Welch) are these. Offset data: exact rational arithmetic
// (reference/offset_reference.py).
#include "analysis/ttest.hpp"

#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;
using testing::throwsWithMessage;

// R's datasets::sleep, extra by group.
const std::vector<double> kSleep1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
const std::vector<double> kSleep2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
constexpr double kDigits = 1e-10;  // ≥ 9 significant digits

TEST(TTest, SleepPaired) {
  // R: t.test(x, y, paired = TRUE): t = -4.06212768338204, df = 9, p = 0.00283289019738427,
  // CI -2.459885763276982 -0.700114236723018; d_z = mean(d)/sd(d) = -1.28455756259105.
  const TTestResult r = pairedTTest(kSleep1, kSleep2, Alternative::TwoSided);
  EXPECT_EQ(r.kind, TTestKind::Paired);
  EXPECT_TRUE(relativelyNear(r.t, -4.06212768338204, kDigits));
  EXPECT_EQ(r.df, 9.0);
  EXPECT_TRUE(relativelyNear(r.p, 0.00283289019738427, kDigits));
  EXPECT_TRUE(relativelyNear(r.meanDiff, -1.58, 1e-14));
  EXPECT_TRUE(relativelyNear(r.ciLow, -2.459885763276982, kDigits));
  EXPECT_TRUE(relativelyNear(r.ciHigh, -0.700114236723018, kDigits));
  EXPECT_TRUE(relativelyNear(r.cohensD, -1.28455756259105, kDigits));
}

TEST(TTest, SleepWelchAndStudent) {
  // R: t.test(extra ~ group, sleep): t = -1.86081346748685, df = 17.7764735161785,
  // p = 0.0793941401873582, CI -3.36548323071171 0.20548323071171.
  const TTestResult w = welchTTest(kSleep1, kSleep2, Alternative::TwoSided);
  EXPECT_TRUE(relativelyNear(w.t, -1.86081346748685, kDigits));
  EXPECT_TRUE(relativelyNear(w.df, 17.7764735161785, kDigits));
  EXPECT_TRUE(relativelyNear(w.p, 0.0793941401873582, kDigits));
  EXPECT_TRUE(relativelyNear(w.ciLow, -3.36548323071171, kDigits));
  EXPECT_TRUE(relativelyNear(w.ciHigh, 0.20548323071171, kDigits));
  // R: var.equal = TRUE: same t, df 18, p = 0.0791867142159382, CI -3.363874032287598 0.203874032287599.
  const TTestResult s = studentTTest(kSleep1, kSleep2, Alternative::TwoSided);
  EXPECT_TRUE(relativelyNear(s.t, -1.86081346748685, kDigits));
  EXPECT_EQ(s.df, 18.0);
  EXPECT_TRUE(relativelyNear(s.p, 0.0791867142159382, kDigits));
  EXPECT_TRUE(relativelyNear(s.ciLow, -3.363874032287598, kDigits));
  EXPECT_TRUE(relativelyNear(s.ciHigh, 0.203874032287599, kDigits));
  // Cohen's d with the pooled SD: -0.83218108134954; Hedges' g = J(18)·d = -0.796935239191122
  // (J from lgamma in R).
  EXPECT_TRUE(relativelyNear(s.cohensD, -0.83218108134954, kDigits));
  EXPECT_TRUE(relativelyNear(s.hedgesG, -0.796935239191122, kDigits));
  EXPECT_TRUE(relativelyNear(w.cohensD, s.cohensD, 1e-15));
}

TEST(TTest, OneSidedAlternatives) {
  // R: paired, alternative = "less": p = 0.00141644509869214, CI upper -0.8669947329707165.
  const TTestResult less = pairedTTest(kSleep1, kSleep2, Alternative::Less);
  EXPECT_TRUE(relativelyNear(less.p, 0.00141644509869214, kDigits));
  EXPECT_TRUE(std::isinf(less.ciLow) && less.ciLow < 0);
  EXPECT_TRUE(relativelyNear(less.ciHigh, -0.8669947329707165, kDigits));
  // R: Welch, alternative = "greater": p = 0.960302929906321, CI lower -3.053381497331606.
  const TTestResult greater = welchTTest(kSleep1, kSleep2, Alternative::Greater);
  EXPECT_TRUE(relativelyNear(greater.p, 0.960302929906321, kDigits));
  EXPECT_TRUE(relativelyNear(greater.ciLow, -3.053381497331606, kDigits));
  EXPECT_TRUE(std::isinf(greater.ciHigh));
}

TEST(TTest, OneSample) {
  // R: t.test(x, mu = 0.5): t = 0.44190338023794, df 9, p = 0.668986623614675,
  // CI -0.529780413526232 2.029780413526233.
  const TTestResult r = oneSampleTTest(kSleep1, 0.5, Alternative::TwoSided);
  EXPECT_TRUE(relativelyNear(r.t, 0.44190338023794, kDigits));
  EXPECT_TRUE(relativelyNear(r.p, 0.668986623614675, kDigits));
  EXPECT_TRUE(relativelyNear(r.ciLow, -0.529780413526232, kDigits));
  EXPECT_TRUE(relativelyNear(r.ciHigh, 2.029780413526233, kDigits));
  EXPECT_TRUE(relativelyNear(r.meanDiff, 0.25, 1e-14));
}

TEST(TTest, OffsetByOneBillion) {
  // R: x <- 1e9 + 0.001 * c(1,2,4,7,11); y <- 1e9 + 0.001 * c(3,5,6,9,10,12); t.test(x, y):
  // t = -1.0945444627709409, df = 7.8714823229385784. (The exact values for these doubles,
  // offset_reference.py, are t = -1.0945705594661222, df = 7.8714823220345607: R subtracts two
  // means rounded to double, and tlab computes what R computes; see r_offset_test.cpp.)
  std::vector<double> x;
  std::vector<double> y;
  for (const int k : {1, 2, 4, 7, 11}) x.push_back(1e9 + 0.001 * k);
  for (const int k : {3, 5, 6, 9, 10, 12}) y.push_back(1e9 + 0.001 * k);
  const TTestResult w = welchTTest(x, y, Alternative::TwoSided);
  EXPECT_TRUE(relativelyNear(w.t, -1.0945444627709409, 1e-9));
  EXPECT_TRUE(relativelyNear(w.df, 7.8714823229385784, 1e-9));
}

TEST(TTest, TinyPValueIsRepresentedNotZero) {
  // 31 values 1 ± 1e-9 (alternating): t ≈ 1/(1e-9/√31) ≈ 5.6e9 on 30 df, so p ≈ 1e-278 — far
  // below 1e-16, where p = 1 - cdf would already be 0. The tail itself is checked against R in
  // distributions_test.cpp (2·pt(-1e10, 30) = 2.07290693051236e-279).
  std::vector<double> x(31);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 + (i % 2 == 0 ? 1.0 : -1.0) * 1e-9;
  const TTestResult r = oneSampleTTest(x, 0.0, Alternative::TwoSided);
  EXPECT_GT(r.t, 1e8);
  EXPECT_GT(r.p, 0.0);
  EXPECT_TRUE(relativelyNear(r.p, studentTPValue(r.t, 30, Alternative::TwoSided), 1e-15));
  EXPECT_LT(r.p, 1e-200);
}

TEST(TTest, NEqualsTwo) {
  // x = (1, 3), y = (2, 6): Welch t = (2 - 4)/√(2/2 + 8/2) = -2/√5, df = 25/(1 + 16) = 25/17
  // (closed form); R agrees: t.test(c(1,3), c(2,6)) gives t = -0.894427190999916, df = 1.47058823529412.
  const std::vector<double> x = {1, 3};
  const std::vector<double> y = {2, 6};
  const TTestResult w = welchTTest(x, y, Alternative::TwoSided);
  EXPECT_TRUE(relativelyNear(w.t, -2 / std::sqrt(5.0), 1e-15));
  EXPECT_TRUE(relativelyNear(w.df, 25.0 / 17.0, 1e-15));
  const TTestResult p = pairedTTest(x, y, Alternative::TwoSided);
  EXPECT_EQ(p.df, 1.0);
  EXPECT_EQ(p.hedgesG, 0.0);  // J(1) = 0: Γ(0) is infinite
}

TEST(TTest, ImpossibleInputsHaveClearErrors) {
  const std::vector<double> one = {1.0};
  const std::vector<double> two = {1.0, 2.0};
  EXPECT_TRUE(throwsWithMessage([&] { welchTTest(one, two, Alternative::TwoSided); }, {"n = 1", "at least 2"}));
  const std::vector<double> a = {5, 5, 5};
  const std::vector<double> b = {7, 7, 7};
  EXPECT_TRUE(throwsWithMessage([&] { welchTTest(a, b, Alternative::TwoSided); },
                                {"zero variance", "both groups are constant", "t would be -infinite"}));
  EXPECT_TRUE(throwsWithMessage([&] { studentTTest(a, a, Alternative::TwoSided); }, {"zero variance", "0/0"}));
  const std::vector<double> c = {1, 2, 3};
  const std::vector<double> d = {0, 1, 2};
  EXPECT_TRUE(throwsWithMessage([&] { pairedTTest(c, d, Alternative::TwoSided); },
                                {"all paired differences are equal", "t would be +infinite"}));
  EXPECT_TRUE(throwsWithMessage([&] { pairedTTest(c, two, Alternative::TwoSided); }, {"equally many"}));
}

}  // namespace
}  // namespace tlab::analysis
