// The pieces of `tlab simulate --calibrate` that live in analysis/: the Nelder-Mead minimiser and
// the likelihood of a published mean and variance; and the questionnaire (Likert) summary of
// `tlab report db`. Expected values: closed forms, and R 4.2.2 where stated.
#include <cmath>

#include "analysis/likert_summary.hpp"
#include "analysis/nelder_mead.hpp"
#include "analysis/summary_likelihood.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;
using testing::throwsWithMessage;

TEST(NelderMead, FindsTheMinimumOfRosenbrocksValley) {
  // f(x, y) = 100 (y - x²)² + (1 - x)², minimum 0 at (1, 1); the classic start (-1.2, 1).
  const auto f = [](const std::vector<double>& p) { return 100 * std::pow(p[1] - p[0] * p[0], 2) + std::pow(1 - p[0], 2); };
  NelderMeadOptions options;
  options.tolerance = 1e-14;
  const NelderMeadResult r = nelderMeadMinimize(f, {-1.2, 1.0}, options);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.x[0], 1.0, 1e-4);
  EXPECT_NEAR(r.x[1], 1.0, 1e-4);
  EXPECT_LT(r.value, 1e-9);
  EXPECT_EQ(nelderMeadMinimize(f, {-1.2, 1.0}, options).evaluations, r.evaluations);  // deterministic
}

TEST(NelderMead, MinimisesAQuadraticInThreeDimensionsAndStopsAtItsLimit) {
  const auto f = [](const std::vector<double>& p) { return std::pow(p[0] - 3, 2) + 2 * std::pow(p[1] + 1, 2) + std::pow(p[2], 2); };
  const NelderMeadResult r = nelderMeadMinimize(f, {0, 0, 0}, {{1, 1, 1}, 1e-14, 4000});
  EXPECT_NEAR(r.x[0], 3, 1e-5);
  EXPECT_NEAR(r.x[1], -1, 1e-5);
  EXPECT_NEAR(r.x[2], 0, 1e-5);
  const NelderMeadResult limited = nelderMeadMinimize(f, {0, 0, 0}, {{1, 1, 1}, 1e-14, 20});
  EXPECT_FALSE(limited.converged);
  EXPECT_LE(limited.evaluations, 20 + 3);
}

TEST(SummaryLikelihood, IsTheNormalMeanAndChiSquaredVarianceDensity) {
  // R: n <- 36; m <- 0.234; v <- 0.035; mu <- 0.25; s2 <- 0.04
  //    dnorm(m, mu, sqrt(s2/n), log=TRUE) + dchisq((n-1)*v/s2, n-1, log=TRUE) + log((n-1)/s2)
  //    = 6.0775672153394069
  EXPECT_TRUE(relativelyNear(summaryLogLikelihood(36, 0.234, 0.035, 0.25, 0.04), 6.0775672153394069, 1e-12));
  // Larger where the model predicts what was published than away from it:
  EXPECT_GT(summaryLogLikelihood(36, 0.234, 0.035, 0.234, 0.035), summaryLogLikelihood(36, 0.234, 0.035, 0.30, 0.035));
  EXPECT_GT(summaryLogLikelihood(36, 0.234, 0.035, 0.234, 0.035), summaryLogLikelihood(36, 0.234, 0.035, 0.234, 0.07));
  EXPECT_EQ(summaryLogLikelihood(36, 0.2, 0.03, 0.2, 0.0), -INFINITY);
  EXPECT_TRUE(throwsWithMessage([] { summaryLogLikelihood(1, 0.2, 0.03, 0.2, 0.03); }, {"n >= 2"}));
}

TEST(LikertSummary, CountsMediansAndRsMeanAndSd) {
  // R: x <- c(5,4,4,2,5,3,4,1); mean 3.5, sd 1.4142135623730951, quantile 2.75, 4, 4.25.
  Table t("q.csv", {"questionnaire", "item", "value"});
  std::size_t line = 1;
  for (const int v : {5, 4, 4, 2, 5, 3, 4, 1}) t.addRow({"post", "ease", std::to_string(v)}, ++line);
  t.addRow({"post", "fun", "3"}, ++line);
  const auto items = summarizeLikert(t, "questionnaire", "item", "value", 5);
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].item, "ease");
  EXPECT_EQ(items[0].n, 8u);
  EXPECT_DOUBLE_EQ(items[0].mean, 3.5);
  EXPECT_TRUE(relativelyNear(items[0].sd, 1.4142135623730951, 1e-15));
  EXPECT_DOUBLE_EQ(items[0].q1, 2.75);
  EXPECT_DOUBLE_EQ(items[0].median, 4.0);
  EXPECT_DOUBLE_EQ(items[0].q3, 4.25);
  EXPECT_EQ(items[0].counts, (std::vector<std::size_t>{1, 1, 1, 3, 2}));
  EXPECT_TRUE(std::isnan(items[1].sd));
  const TextTable table = likertTable(items, 5, "Questionnaire 'post'");
  EXPECT_EQ(table.header.back(), "5");
  EXPECT_EQ(table.rows[0][3], "4");
  t.addRow({"post", "ease", "6"}, ++line);
  EXPECT_TRUE(throwsWithMessage([&] { summarizeLikert(t, "questionnaire", "item", "value", 5); },
                                {"q.csv:11", "column 'value'", "not a point of the 1..5 scale"}));
}

}  // namespace
}  // namespace tlab::analysis
