// Pairwise t-tests with p-value adjustment and JZS Bayes factors against R: pairwise.t.test +
// p.adjust (R 4.2.2) and BayesFactor::ttestBF (0.9.12-4.4), values from
// reference/mixed_models.R (reference/mixed/expected.csv). Each test prints its largest relative
// difference.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/bayes_factor.hpp"
#include "analysis/csv_reader.hpp"
#include "analysis/p_adjust.hpp"
#include "analysis/pairwise_tests.hpp"
#include "analysis/table_tests.hpp"
#include "tests/analysis/mixed_reference.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::MixedReference;
using testing::referencePath;
using testing::RelativeDifferences;

const MixedReference& reference() {
  static const MixedReference r;
  return r;
}

std::string data(const char* name) { return std::string(TLAB_TEST_DATA) + "/analysis/" + name; }

TEST(PAdjust, EqualsRWithTiesAndAMissingValue) {
  const std::vector<double> p = {0.01, 0.04, 0.03, 0.005, 0.2, 0.04, std::nan("")};
  RelativeDifferences diff("p.adjust");
  for (const char* method : {"holm", "bonferroni", "BH", "BY", "hochberg"}) {
    const auto adjusted = pAdjust(p, parsePAdjustMethod(method));
    for (std::size_t k = 0; k + 1 < p.size(); ++k)
      diff.check(method, std::to_string(k + 1), adjusted[k], reference().at("p_adjust", method, std::to_string(k + 1), "p_adjusted"), 1e-15);
    EXPECT_TRUE(std::isnan(adjusted.back()));
  }
  EXPECT_EQ(pAdjust(p, PAdjustMethod::None)[2], 0.03);
  EXPECT_TRUE(testing::throwsWithMessage([] { parsePAdjustMethod("tukey"); }, {"'tukey'", "holm"}));
}

void comparePairwise(const PairwiseResult& r, const char* model, const char* method, bool raw) {
  RelativeDifferences diff(std::string(model) + " " + method);
  ASSERT_EQ(r.rows.size(), 3u);
  for (const auto& row : r.rows) {
    // R's matrix holds row level i > column level j; either order names the same pair.
    std::string key = row.first + "|" + row.second;
    if (!reference().has(model, method, key, "p_adjusted")) key = row.second + "|" + row.first;
    if (raw) diff.check("p", key, row.p, reference().at(model, method, key, "p"), 1e-10);
    diff.check("p_adjusted", key, row.pAdjusted, reference().at(model, method, key, "p_adjusted"), 1e-10);
  }
}

TEST(Pairwise, PairedTestsOfSubjectMeansEqualPairwiseTTest) {
  const Table t = readCsvFile(referencePath("crossed.csv"));
  for (const char* method : {"holm", "bonferroni", "BH", "hochberg", "none"}) {
    PairwiseRequest request;
    request.dv = "rt";
    request.within = "method";
    request.subject = "participant";
    request.adjust = parsePAdjustMethod(method);
    comparePairwise(pairwiseTTestsOnTable(t, request), "pairwise_within", method, true);
  }
}

TEST(Pairwise, PooledSdAndWelchBetweenGroupsEqualPairwiseTTest) {
  const Table t = readCsvFile(data("plant_growth.csv"));
  for (const char* method : {"holm", "bonferroni", "BH", "hochberg", "none"}) {
    PairwiseRequest request;
    request.dv = "weight";
    request.between = "group";
    request.adjust = parsePAdjustMethod(method);
    const PairwiseResult r = pairwiseTTestsOnTable(t, request);
    EXPECT_EQ(r.rows[0].df, 27.0);  // Σ (n_g − 1) over the three groups
    comparePairwise(r, "pairwise_between", method, true);
  }
  PairwiseRequest welch;
  welch.dv = "weight";
  welch.between = "group";
  welch.poolSd = false;
  comparePairwise(pairwiseTTestsOnTable(t, welch), "pairwise_between_welch", "holm", false);
}

TEST(BayesFactor, JzsEqualsTtestBF) {
  const Table sleep = readCsvFile(data("sleep.csv"));
  const Table plants = readCsvFile(data("plant_growth.csv"));
  RelativeDifferences diff("ttestBF");
  TTestRequest paired;
  paired.dv = "extra";
  paired.within = "group";
  paired.subject = "ID";
  const TTestResult p = tTestOnTable(sleep, paired);
  diff.check("bf10", "paired medium", jzsBayesFactor10(p, kMediumCauchyScale), reference().at("bayes", "paired", "medium", "bf10"), 1e-6);
  diff.check("bf10", "paired wide", jzsBayesFactor10(p, 1.0), reference().at("bayes", "paired", "wide", "bf10"), 1e-6);
  const Table group1 = sleep.rowsWhere("group", "1");
  TTestRequest one;
  one.dv = "extra";
  one.mu = 0.5;
  diff.check("bf10", "one-sample", jzsBayesFactor10(tTestOnTable(group1, one), kMediumCauchyScale),
             reference().at("bayes", "one_sample", "medium", "bf10"), 1e-6);
  TTestRequest two;
  two.dv = "extra";
  two.between = "group";  // Welch by default: the Bayes factor uses the pooled t all the same
  const TTestResult w = tTestOnTable(sleep, two);
  diff.check("bf10", "two-sample", jzsBayesFactor10(w, kMediumCauchyScale), reference().at("bayes", "two_sample", "medium", "bf10"), 1e-6);
  diff.check("bf10", "two-sample ultrawide", jzsBayesFactor10(w, std::sqrt(2.0)),
             reference().at("bayes", "two_sample", "ultrawide", "bf10"), 1e-6);
  TTestRequest trt;
  trt.dv = "weight";
  trt.between = "group";
  Table trtOnly("plants", {"weight", "group"});
  for (std::size_t r = 0; r < plants.rowCount(); ++r)
    if (plants.text(r, 1) != "ctrl") trtOnly.addRow({plants.text(r, 0), plants.text(r, 1)}, r + 2);
  diff.check("bf10", "PlantGrowth trt1 vs trt2", jzsBayesFactor10(tTestOnTable(trtOnly, trt), kMediumCauchyScale),
             reference().at("bayes", "plant_growth", "medium", "bf10"), 1e-6);
}

TEST(BayesFactor, LimitsAreAnalytic) {
  // t = 0: BF10 < 1 and falls as n grows (evidence for the null accumulates, Rouder et al. Fig. 2).
  const double small = std::exp(jzsLogBayesFactor10(0.0, 10.0, 9.0, kMediumCauchyScale));
  const double large = std::exp(jzsLogBayesFactor10(0.0, 1000.0, 999.0, kMediumCauchyScale));
  EXPECT_LT(small, 1.0);
  EXPECT_LT(large, small);
  // Huge t: no overflow, finite log BF.
  EXPECT_TRUE(std::isfinite(jzsLogBayesFactor10(80.0, 50.0, 49.0, kMediumCauchyScale)));
  TTestResult oneSided = oneSampleTTest(std::vector<double>{1, 2, 3, 4.5}, 0.0, Alternative::Greater);
  EXPECT_TRUE(testing::throwsWithMessage([&] { jzsBayesFactor10(oneSided, 0.7); }, {"two-sided"}));
}

}  // namespace
}  // namespace tlab::analysis
