// Reproduction of the seeds' published statistics. Expected values are closed forms of the printed
// numbers (computed by hand / python3, shown in the comments) and R's pt/pf for the p-values.
#include "analysis/reproduce_carnecky.hpp"
#include "analysis/reproduce_elmqvist.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;

TEST(ReproduceCarnecky, WelchReproducesTable1AndPairedDoesNot) {
  // Welch with n = 36 per group: df = 35 (v1 + v2)² / (v1² + v2²) and t = (m1 - m2)/√((v1 + v2)/36):
  //   NV vs AB: df = 67.65812859383168 → 68, t = -0.6137949055234261 (printed 0.62, sign slip)
  //   AB vs IT: df = 67.22626025791325 → 67, t = -1.9789201600873139 (printed -1.98)
  //   NV vs IT: df = 61.369863013698634 → 61, t = -2.653407512722354 (printed -2.66, within rounding)
  // One-sided p (R: pt(t, df) at the values above): 0.270704573571675, 0.0259616737851679,
  // 0.00506589827269784 (printed .270, .026, .005).
  const CarneckyReproduction r = reproduceCarnecky();
  ASSERT_EQ(r.rows.size(), 3u);
  const double dfs[] = {67.65812859383168, 67.22626025791325, 61.369863013698634};
  const double ts[] = {-0.6137949055234261, -1.9789201600873139, -2.653407512722354};
  const double ps[] = {0.270704573571675, 0.0259616737851679, 0.00506589827269784};
  const int printedDf[] = {68, 67, 61};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& welch = r.rows[i].checks[0];
    const auto& student = r.rows[i].checks[1];
    const auto& paired = r.rows[i].checks[2];
    ASSERT_EQ(welch.kind, TTestKind::Welch);
    EXPECT_TRUE(relativelyNear(welch.df, dfs[i], 1e-13));
    EXPECT_EQ(static_cast<int>(std::lround(welch.df)), printedDf[i]);
    EXPECT_TRUE(relativelyNear(welch.t, ts[i], 1e-13));
    EXPECT_TRUE(relativelyNear(welch.pOneSided, ps[i], 1e-10));
    EXPECT_TRUE(welch.consistent()) << "row " << i;
    EXPECT_TRUE(welch.tConsistent && welch.dfConsistent && welch.pConsistent);
    // Student: same t (n1 = n2) but df 70.
    EXPECT_EQ(student.df, 70.0);
    EXPECT_TRUE(student.tConsistent);
    EXPECT_FALSE(student.dfConsistent);
    EXPECT_FALSE(student.consistent());
    // Paired: df 35 can never print as 68/67/61; the printed t would need r ≈ 0.
    EXPECT_EQ(paired.df, 35.0);
    EXPECT_FALSE(paired.consistent());
    EXPECT_TRUE(paired.impliedCorrelationRange.contains(paired.impliedCorrelation));
    EXPECT_LT(std::fabs(paired.impliedCorrelation), 0.05);
  }
  // Row 3's printed |t| = 2.66 lies outside the point value 2.653 but inside the rounding range.
  EXPECT_LT(r.rows[2].checks[0].absTRange.lo, 2.655);
  EXPECT_GT(r.rows[2].checks[0].absTRange.hi, 2.665);
  // Printed t = 0.62 for NV (0.234) vs AB (0.264) has the wrong sign; the text's p = 0.54 is the
  // two-sided Welch p (2 × 0.2707 = 0.5414).
  EXPECT_FALSE(r.rows[0].signMatchesMeans);
  EXPECT_TRUE(r.rows[1].signMatchesMeans);
  EXPECT_TRUE(r.rows[0].textPIsTwoSided);
  EXPECT_FALSE(r.rows[0].textPIsOneSided);
  EXPECT_TRUE(r.rows[2].textPIsOneSided);
}

TEST(ReproduceElmqvist, EveryReportedFIsConsistentAndCorrelationsArePossible) {
  // R: pf(F, 1, 15, lower.tail = FALSE): 49.54 → 4.014318e-06, 6.28 → 0.02421757,
  // 4.74 → 0.04584869, 4.12 → 0.060506, .068 → 0.797817376392113 (printed .797: consistent only
  // through the rounding of F = .068 ∈ [.0675, .0685], whose p range is
  // [0.797093233727954, 0.798544379242845]).
  const ElmqvistReproduction r = reproduceElmqvist();
  ASSERT_EQ(r.fTests.size(), 9u);
  for (const auto& c : r.fTests) {
    EXPECT_TRUE(c.pConsistent) << c.published.measure;
    EXPECT_TRUE(c.correlationPossible) << c.published.measure;
    EXPECT_EQ(c.df2, 15.0);
  }
  EXPECT_TRUE(relativelyNear(r.fTests[0].pComputed, 4.014318e-06, 1e-6));
  EXPECT_TRUE(relativelyNear(r.fTests[5].pComputed, 0.02421757, 1e-6));
  EXPECT_TRUE(relativelyNear(r.fTests[8].pComputed, 0.797817376392113, 1e-10));
  EXPECT_TRUE(relativelyNear(r.fTests[8].pRange.lo, 0.797093233727954, 1e-10));
  EXPECT_TRUE(relativelyNear(r.fTests[8].pRange.hi, 0.798544379242845, 1e-10));
  EXPECT_FALSE(r.fTests[8].pRange.contains(0.797));            // the point .797 itself is outside,
  EXPECT_TRUE(r.fTests[8].pRange.intersects({0.7965, 0.7975}));  // its rounding interval is not
  // Overall time: s_d = |65.17 - 28.69|·4/√49.54 = 20.7321..., r = (27.75² + 11.02² - s_d²)/(2·27.75·11.02)
  // = 0.754965... (closed form).
  const double sd = 36.48 * 4 / std::sqrt(49.54);
  const double expected = (27.75 * 27.75 + 11.02 * 11.02 - sd * sd) / (2 * 27.75 * 11.02);
  EXPECT_TRUE(relativelyNear(r.fTests[0].impliedCorrelation, expected, 1e-13));
  EXPECT_NEAR(r.fTests[0].impliedCorrelation, 0.755, 0.001);
  EXPECT_EQ(r.designCount, 192);
  EXPECT_EQ(r.reportedTaskCount, 384);
  EXPECT_EQ(r.designCount * r.tasksPerScenario, r.reportedTaskCount);
}

TEST(ReproduceElmqvist, ImpliedCorrelationDetectsImpossibleSummaries) {
  // Means 10 vs 0 with SDs 1 and 1 on 16 subjects: F(1,15) = 1 would need s_d = 40, i.e.
  // r = (1 + 1 - 1600)/2 = -799 — impossible.
  EXPECT_DOUBLE_EQ(impliedWithinSubjectCorrelation(10, 1, 0, 1, 1, 16), -799.0);
}

TEST(Interval, RoundingIntervalsAndArithmetic) {
  const ReportedValue v = ReportedValue::parse(".068");
  EXPECT_EQ(v.decimals, 3);
  EXPECT_DOUBLE_EQ(v.interval().lo, 0.0675);
  EXPECT_EQ(ReportedValue::parse("140.0").decimals, 1);
  EXPECT_EQ(ReportedValue::parse("68").decimals, 0);
  const Interval a{1, 2};
  const Interval b{-3, 4};
  EXPECT_DOUBLE_EQ((a * b).lo, -6);
  EXPECT_DOUBLE_EQ((a * b).hi, 8);
  EXPECT_DOUBLE_EQ(square(b).lo, 0);
  EXPECT_DOUBLE_EQ(square(b).hi, 16);
  EXPECT_THROW(a / b, std::domain_error);
}

}  // namespace
}  // namespace tlab::analysis
