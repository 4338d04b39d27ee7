// tlab reproduce --table: the generic Welch / Student / paired reproduction of printed two-group
// comparisons. Expected values: closed forms (shown) and R 4.2.2's pt.
#include <filesystem>
#include <fstream>

#include "analysis/reproduce_carnecky.hpp"
#include "analysis/reproduce_table.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;

std::string writeTable(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

// Unequal groups: m1 = 10, sd1 = 2, n1 = 10; m2 = 12, sd2 = 4, n2 = 20.
// Student: s² = (9·4 + 19·16)/28 = 340/28, t = -2/√(340/28 · 0.15) = -1.4819171472698969, df 28,
//   two-sided p = 0.14953009055425986 (R).
// Welch: t = -2/√(0.4 + 0.8) = -1.8257418583505538, df = 1.44/(0.16/9 + 0.64/19) = 27.98181818181818.
TEST(ReproduceTable, StudentAndWelchDifferWithUnequalGroups) {
  const std::string path = writeTable("tlab_reproduce_unequal.csv",
                                      "first,second,mean1,sd1,n1,mean2,sd2,n2,df,t,p\n"
                                      "A,B,10.0,2.0,10,12.0,4.0,20,28,-1.48,.150\n");
  const auto rows = reproduceTable(path);
  std::filesystem::remove(path);
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0].checks.size(), 2u);  // no paired reading with n1 != n2
  const auto& welch = rows[0].checks[0];
  const auto& student = rows[0].checks[1];
  EXPECT_TRUE(relativelyNear(welch.t, -1.8257418583505538, 1e-13));
  EXPECT_TRUE(relativelyNear(welch.df, 27.98181818181818, 1e-13));
  EXPECT_TRUE(welch.dfRange.contains(welch.df));
  EXPECT_FALSE(welch.tConsistent);
  EXPECT_FALSE(welch.consistent());
  EXPECT_TRUE(relativelyNear(student.t, -1.4819171472698969, 1e-13));
  EXPECT_EQ(student.df, 28.0);
  EXPECT_TRUE(student.pRange.contains(0.14953009055425986));  // two-sided by default
  EXPECT_TRUE(student.consistent());
}

// The CSV form of Carnecky's Table 1 gives exactly the checks of `reproduce carnecky`.
TEST(ReproduceTable, CarneckyTableAsCsvMatchesTheBuiltInReproduction) {
  const auto rows = reproduceTable(std::string(TLAB_TEST_DATA) + "/analysis/carnecky_table1.csv");
  const CarneckyReproduction builtIn = reproduceCarnecky();
  ASSERT_EQ(rows.size(), builtIn.rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].checks.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      const auto& a = rows[i].checks[k];
      const auto& b = builtIn.rows[i].checks[k];
      EXPECT_EQ(a.kind, b.kind);
      EXPECT_EQ(a.consistent(), b.consistent()) << "row " << i << " test " << k;
      EXPECT_EQ(a.dfRange.lo, b.dfRange.lo);
      EXPECT_EQ(a.pRange.hi, b.pRange.hi);
    }
  }
}

TEST(ReproduceTable, BadTablesNameFileLineAndColumn) {
  const std::string noSpread = writeTable("tlab_reproduce_nospread.csv", "mean1,n1,mean2,n2\n1,10,2,10\n");
  EXPECT_TRUE(testing::throwsWithMessage([&] { reproduceTable(noSpread); }, {"var1", "sd1"}));
  const std::string badN = writeTable("tlab_reproduce_badn.csv", "mean1,var1,n1,mean2,var2,n2\n1,1,10,2,1,1.5\n");
  EXPECT_TRUE(testing::throwsWithMessage([&] { reproduceTable(badN); }, {"tlab_reproduce_badn.csv:2", "n2"}));
  const std::string badTails = writeTable("tlab_reproduce_tails.csv", "mean1,var1,n1,mean2,var2,n2,p,p_tails\n1,1,10,2,1,10,.5,3\n");
  EXPECT_TRUE(testing::throwsWithMessage([&] { reproduceTable(badTails); }, {"p_tails"}));
  for (const auto& p : {noSpread, badN, badTails}) std::filesystem::remove(p);
}

}  // namespace
}  // namespace tlab::analysis
