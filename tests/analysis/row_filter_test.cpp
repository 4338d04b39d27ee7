// Row filters of `tlab stats` (--where) and R's na.omit for the dependent variable.
#include "analysis/row_filter.hpp"

#include <gtest/gtest.h>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {
namespace {

Table sample() {
  Table t("t.csv", {"phase", "task", "rt"});
  t.addRow({"test", "a", "1.5"}, 2);
  t.addRow({"training", "a", "9"}, 3);
  t.addRow({"test", "b", ""}, 4);
  t.addRow({"test", "c", " NA "}, 5);
  t.addRow({"test", "b", "2"}, 6);
  return t;
}

TEST(RowFilter, ParsesColumnAndValues) {
  const RowFilter f = parseRowFilter("task= a , b");
  EXPECT_EQ(f.column, "task");
  EXPECT_EQ(f.values, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(parseRowFilter("phase=test").values, std::vector<std::string>{"test"});
  EXPECT_THROW(parseRowFilter("phase"), AnalysisError);
  EXPECT_THROW(parseRowFilter("=test"), AnalysisError);
  EXPECT_THROW(parseRowFilter("phase=,"), AnalysisError);
}

TEST(RowFilter, KeepsRowsThatPassEveryFilterWithTheirOrigins) {
  const Table kept = rowsMatching(sample(), {parseRowFilter("phase=test"), parseRowFilter("task=b,c")});
  ASSERT_EQ(kept.rowCount(), 3u);
  EXPECT_EQ(kept.where(0), "t.csv:4");
  EXPECT_EQ(kept.where(1), "t.csv:5");
  EXPECT_EQ(kept.where(2), "t.csv:6");
  EXPECT_EQ(rowsMatching(sample(), {}).rowCount(), 5u);
  EXPECT_THROW(rowsMatching(sample(), {parseRowFilter("nope=1")}), AnalysisError);
}

TEST(RowFilter, DropsEmptyAndNaCellsOfTheColumnOnly) {
  const WithoutMissing w = dropMissing(sample(), "rt");
  EXPECT_EQ(w.dropped, 2u);
  ASSERT_EQ(w.table.rowCount(), 3u);
  EXPECT_EQ(w.table.numericColumn("rt"), (std::vector<double>{1.5, 9.0, 2.0}));
  EXPECT_EQ(dropMissing(sample(), "task").dropped, 0u);
  EXPECT_TRUE(isMissingCell("  "));
  EXPECT_FALSE(isMissingCell("NaN"));  // not R's NA: the number check refuses it with its line
}

}  // namespace
}  // namespace tlab::analysis
