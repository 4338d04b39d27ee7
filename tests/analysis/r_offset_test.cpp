// Offset data analysed exactly as R analyses them (issue 15, part 5). The data are off + k·u for
// fixed integers k (u = 2^-20, sd ≈ 1e-3; at 1e12 also u = 2^-10, sd ≈ 1): the same IEEE double
// operations in R and C++, so both see the same doubles. Every expected value was printed by
// R 4.2.2 (Debian 12 r-base-core) running tests/analysis/reference/offset_r_reference.R, e.g.
//   x <- 1e9 + a * 2^-20; y <- 1e9 + b * 2^-20; t.test(x, y)   # welch a-b
//   summary(aov(y ~ cond + Error(subj / cond), data = r))        # within F, p
// and is compared to 1e-9 relative (1e-12 for R's mean and var themselves). R's t.test uses
// mean(x) - mean(y) of means rounded to double, so at 1e9 its t statistics differ from the exact
// values by 5e-5 (Welch, Student) and 1.6e-4 (one-sample) relative: tlab before this change
// (shifted, compensated sums) gave Welch t = -4.7751582854776098 here, R gives -4.7753968709293915.
// These tests fail for any algorithm that is more (or less) exact than R's.
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "analysis/anova.hpp"
#include "analysis/anova_design.hpp"
#include "analysis/csv_reader.hpp"
#include "analysis/r_moments.hpp"
#include "analysis/rank_tests.hpp"
#include "analysis/ttest.hpp"
#include "tests/analysis/test_support.hpp"
#include "tests/support/run_command.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;
using testing::throwsWithMessage;

constexpr double kR = 1e-9;

const std::vector<int> kA = {398, -1089, 378, -129, -2388, -398, 447, -780, -269, -1458, 1484, 704};
const std::vector<int> kB = {1858, 2068, 2058, 1854, 2558, 3700, 1229, -1183, 1587, 2189, 2898, 897, 818, 1222, 2393};
const std::vector<int> kC = {1794, 1130, 287, 1923, 1240, 337, 11, 897, 676, 868};
const std::vector<int> kPre = {-657, -1033, 102, -507, -1322, -159, -633, -1378, 325, -925, -296, 852, -3226, 1327};
const std::vector<int> kPost = {1076, 1119, 2385, 894, 1146, 707, 1852, 145, 1971, 1042, 1342, 1192, 1768, 959};
const std::vector<int> kThird = {1433, 972, 1591, 689, 775, 1912, 705, 2225, -1270, -71, 881, -2224, -95, 562};

// R's t.test: statistic, parameter, p.value, conf.int.
struct RTTest {
  double t, df, p, ciLow, ciHigh;
};

struct OffsetCase {
  double offset, unit;
  double meanAMinusOffset, varA, covPrePost;
  RTTest oneSample, paired, student, welch;
  double betweenF, betweenP, withinF, withinP;
};

const OffsetCase kCases[] = {
    {1e6, 0x1p-20, -0.00024636590387672186, 1.0143487474344914e-06, 1.7973993985483851e-08,
     {-0.84737876650047705, 11, 0.41484086636824469, 999999.99911372224, 1000000.000393546},
     {5.4838916023022586, 13, 0.00010498261385322607, 0.0010373845944288834, 0.0023860337230934381},
     {-4.7458367007067839, 25, 7.1996903214846536e-05, -0.0027369904021789159, -0.0010803771980981498},
     {-4.7751583437273393, 24.220160735718661, 7.1962220628533306e-05, -0.0027332503145996476, -0.0010841172856774187},
     13.69391813694161, 4.3425221782916297e-05, 9.8626618208917538, 0.00064955402557324436},
    {1e9, 0x1p-20, -0.00024640560150146484, 1.0143487491570176e-06, 1.7973993985483851e-08,
     {-0.84751530628326144, 11, 0.41476799775032469, 999999999.99911368, 1000000000.0003935},
     {5.4838916023022586, 13, 0.00010498261385322607, 0.0010373845944288834, 0.0023860337230934381},
     {-4.7460737629044987, 25, 7.1952664648262376e-05, -0.0027370857473317566, -0.0010804725412424622},
     {-4.7753968709293915, 24.220160740959333, 7.1918411790695833e-05, -0.0027333456596797252, -0.0010842126288944935},
     13.69391813694161, 4.3425221782916297e-05, 9.8626618208917538, 0.00064955402557324436},
    {1e12, 0x1p-10, -0.2523193359375, 1.0636217539960688, 0.018847098717322715,
     {-0.84751530628326144, 11, 0.41476799775032469, 999999999999.09241, 1000000000000.403},
     {5.4838916023022586, 13, 0.00010498261385322607, 1.0622818246951766, 2.4432985324476806},
     {-4.7460737629044987, 25, 7.1952664648262376e-05, -2.8027758052677187, -1.1064038822322813},
     {-4.7753968709293915, 24.220160740959333, 7.1918411790695833e-05, -2.7989459555120386, -1.1102337319879614},
     13.69391813694161, 4.3425221782916297e-05, 9.8626618208917538, 0.00064955402557324436},
};

std::vector<double> values(const std::vector<int>& ks, double offset, double unit) {
  std::vector<double> out;
  for (const int k : ks) out.push_back(offset + k * unit);
  return out;
}

::testing::AssertionResult matchesR(const TTestResult& r, const RTTest& expected) {
  for (const auto& [actual, want, what] : {std::tuple{r.t, expected.t, "t"}, {r.df, expected.df, "df"},
                                           {r.p, expected.p, "p"}, {r.ciLow, expected.ciLow, "CI low"},
                                           {r.ciHigh, expected.ciHigh, "CI high"}}) {
    const auto near = relativelyNear(actual, want, kR);
    if (!near) return ::testing::AssertionFailure() << what << ": " << near.message();
  }
  return ::testing::AssertionSuccess();
}

class ROffset : public ::testing::TestWithParam<OffsetCase> {};

TEST_P(ROffset, MeanVarianceAndCovarianceAreRs) {
  const OffsetCase& c = GetParam();
  const auto a = values(kA, c.offset, c.unit);
  EXPECT_TRUE(relativelyNear(rMean(a) - c.offset, c.meanAMinusOffset, 1e-12));
  EXPECT_TRUE(relativelyNear(rVariance(a), c.varA, 1e-12));
  EXPECT_TRUE(relativelyNear(rCovariance(values(kPre, c.offset, c.unit), values(kPost, c.offset, c.unit)),
                             c.covPrePost, 1e-12));
}

TEST_P(ROffset, TTestsAreRs) {
  const OffsetCase& c = GetParam();
  const auto a = values(kA, c.offset, c.unit);
  const auto b = values(kB, c.offset, c.unit);
  EXPECT_TRUE(matchesR(oneSampleTTest(a, c.offset, Alternative::TwoSided), c.oneSample));
  EXPECT_TRUE(matchesR(pairedTTest(values(kPost, c.offset, c.unit), values(kPre, c.offset, c.unit),
                                   Alternative::TwoSided),
                       c.paired));
  EXPECT_TRUE(matchesR(studentTTest(a, b, Alternative::TwoSided), c.student));
  EXPECT_TRUE(matchesR(welchTTest(a, b, Alternative::TwoSided), c.welch));
}

std::string csvRow(const char* a, const char* b, double y) {
  char line[128];
  std::snprintf(line, sizeof line, "%s,%s,%.17g\n", a, b, y);
  return line;
}

TEST_P(ROffset, BetweenAndRepeatedMeasuresAnovaAreRs) {
  const OffsetCase& c = GetParam();
  std::string between = "s,g,y\n";
  int subject = 0;
  for (const auto& [name, ks] : {std::pair{"a", kA}, {"b", kB}, {"c", kC}})
    for (const double y : values(ks, c.offset, c.unit)) between += csvRow(std::to_string(++subject).c_str(), name, y);
  const AnovaResult b = anova(makeAnovaDesign(parseCsv(between, "between.csv"), "y", {"g"}, {}, ""));
  EXPECT_TRUE(relativelyNear(b.effects.at(0).F, c.betweenF, kR));
  EXPECT_TRUE(relativelyNear(b.effects.at(0).p, c.betweenP, kR));
  std::string within = "subj,cond,y\n";
  for (const auto& [name, ks] : {std::pair{"pre", kPre}, {"post", kPost}, {"third", kThird}}) {
    const auto ys = values(ks, c.offset, c.unit);
    for (std::size_t s = 0; s < ys.size(); ++s) within += csvRow(std::to_string(s + 1).c_str(), name, ys[s]);
  }
  const AnovaResult w = anova(makeAnovaDesign(parseCsv(within, "within.csv"), "y", {}, {"cond"}, "subj"));
  EXPECT_TRUE(relativelyNear(w.effects.at(0).F, c.withinF, kR));
  EXPECT_TRUE(relativelyNear(w.effects.at(0).p, c.withinP, kR));
}

TEST_P(ROffset, RankTestsAreRs) {
  // R (every offset): wilcox.test(post, pre, paired = TRUE): V = 103, p = 0.00036621093750000016;
  // wilcox.test(a, b): W = 14, p = 5.8099869649203345e-05; friedman.test(cbind(pre, post, third)):
  // chi² = 14.285714285714286, p = 0.00079049032311996614.
  const OffsetCase& c = GetParam();
  const auto pre = values(kPre, c.offset, c.unit);
  const auto post = values(kPost, c.offset, c.unit);
  const auto third = values(kThird, c.offset, c.unit);
  const WilcoxonSignedRankResult w = wilcoxonSignedRankTest(post, pre, 0.0, Alternative::TwoSided);
  EXPECT_EQ(w.V, 103.0);
  EXPECT_TRUE(relativelyNear(w.p, 0.00036621093750000016, kR));
  const MannWhitneyResult m = mannWhitneyTest(values(kA, c.offset, c.unit), values(kB, c.offset, c.unit),
                                              Alternative::TwoSided);
  EXPECT_EQ(m.W, 14.0);
  EXPECT_TRUE(relativelyNear(m.p, 5.8099869649203345e-05, kR));
  Eigen::MatrixXd y(static_cast<Eigen::Index>(pre.size()), 3);
  for (std::size_t s = 0; s < pre.size(); ++s) y.row(static_cast<Eigen::Index>(s)) << pre[s], post[s], third[s];
  const FriedmanResult f = friedmanTest(y);
  EXPECT_TRUE(relativelyNear(f.chiSquared, 14.285714285714286, kR));
  EXPECT_TRUE(relativelyNear(f.p, 0.00079049032311996614, kR));
}

INSTANTIATE_TEST_SUITE_P(Offsets, ROffset, ::testing::ValuesIn(kCases), [](const auto& info) {
  return "Offset1e" + std::to_string(static_cast<int>(std::lround(std::log10(info.param.offset))));
});

TEST(ROffset, EssentiallyConstantDataAreRefusedAsRRefusesThem) {
  // R: t.test(1e12 + a * 2^-20, mu = 1e12) stops with "data are essentially constant" (the
  // standard error 2.9e-4 is below 10 eps · 1e12 = 2.2e-3); so does welch/student on a and b.
  const auto a = values(kA, 1e12, 0x1p-20);
  const auto b = values(kB, 1e12, 0x1p-20);
  EXPECT_TRUE(throwsWithMessage([&] { oneSampleTTest(a, 1e12, Alternative::TwoSided); }, {"essentially constant"}));
  EXPECT_TRUE(throwsWithMessage([&] { welchTTest(a, b, Alternative::TwoSided); }, {"essentially constant"}));
  EXPECT_TRUE(throwsWithMessage([&] { studentTTest(a, b, Alternative::TwoSided); }, {"essentially constant"}));
}

TEST(ROffset, TlabStatsOnACsvFileGivesRsWelchTest) {
  // As a user meets it: the 1e9 data written to CSV with 17 digits, `tlab stats ttest --json`,
  // compared with R's t.test(x, y) on the same doubles (offset_r_reference.R, "welch a-b" at 1e9).
  const auto dir = ::tlab::testing::freshDir("r_offset_cli");
  const std::string csv = (dir / "offset.csv").string();
  {
    std::ofstream out(csv);
    out << "group,y\n";
    for (const auto& [name, ks] : {std::pair{"a", kA}, {"b", kB}})
      for (const double y : values(ks, 1e9, 0x1p-20)) {
        char line[64];
        std::snprintf(line, sizeof line, "%s,%.17g\n", name, y);
        out << line;
      }
  }
  const auto r = ::tlab::testing::runCommand(std::string(TLAB_EXE) + " stats ttest " + csv + " --dv y --between group --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const RTTest& welch = kCases[1].welch;
  EXPECT_TRUE(relativelyNear(j["t"].get<double>(), welch.t, kR));
  EXPECT_TRUE(relativelyNear(j["df"].get<double>(), welch.df, kR));
  EXPECT_TRUE(relativelyNear(j["p"].get<double>(), welch.p, kR));
  EXPECT_TRUE(relativelyNear(j["ci_low"].get<double>(), welch.ciLow, kR));
  EXPECT_TRUE(relativelyNear(j["ci_high"].get<double>(), welch.ciHigh, kR));
}

}  // namespace
}  // namespace tlab::analysis
