// CSV reader (RFC 4180) and Table: quoting, CRLF, embedded line breaks, and file:line errors.
#include "analysis/csv_reader.hpp"

#include "analysis/factor.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::throwsWithMessage;

TEST(CsvReader, QuotedFieldsCrlfAndEmbeddedNewlines) {
  const std::string text =
      "\xEF\xBB\xBF" "subject,\"condition, long\",value\r\n"
      "s1,\"a \"\"quoted\"\" label\",1.5\r\n"
      "s2,\"two\nlines\",-2e-3\r\n"
      "\r\n"
      "s3,,  7 \r\n";
  const Table t = parseCsv(text, "mem.csv");
  ASSERT_EQ(t.columnCount(), 3u);
  ASSERT_EQ(t.rowCount(), 3u);
  EXPECT_EQ(t.columnNames()[1], "condition, long");
  EXPECT_EQ(t.text(0, 1), "a \"quoted\" label");
  EXPECT_EQ(t.text(1, 1), "two\nlines");
  EXPECT_EQ(t.text(2, 1), "");
  EXPECT_DOUBLE_EQ(t.number(1, 2), -2e-3);
  EXPECT_DOUBLE_EQ(t.number(2, 2), 7.0);
  // Line numbers count physical lines: the quoted field spans lines 3-4, line 5 is blank, so the
  // last record is on line 6.
  EXPECT_EQ(t.where(1), "mem.csv:3");
  EXPECT_EQ(t.where(2), "mem.csv:6");
}

TEST(CsvReader, ErrorsNameFileAndLine) {
  EXPECT_TRUE(throwsWithMessage([] { parseCsv("a,b\n1,2\n3\n", "x.csv"); }, {"x.csv:3", "expected 2 fields, found 1"}));
  EXPECT_TRUE(throwsWithMessage([] { parseCsv("a,b\n1,\"open\n", "x.csv"); }, {"x.csv:2", "never closed"}));
  EXPECT_TRUE(throwsWithMessage([] { parseCsv("a,b\n1,\"x\"y\n", "x.csv"); }, {"x.csv:2", "after a closing double quote"}));
  EXPECT_TRUE(throwsWithMessage([] { parseCsv("a,b\n1,x\"y\n", "x.csv"); }, {"x.csv:2", "stray double quote"}));
  EXPECT_TRUE(throwsWithMessage([] { parseCsv("", "x.csv"); }, {"x.csv", "empty"}));
  EXPECT_TRUE(throwsWithMessage([] { parseCsv("a,a\n1,2\n", "x.csv"); }, {"duplicate column name 'a'"}));
  EXPECT_TRUE(throwsWithMessage([] { readCsvFile("/nonexistent/file.csv"); }, {"/nonexistent/file.csv", "cannot open"}));
}

TEST(Table, NonNumericValueNamesFileLineAndColumn) {
  const Table t = parseCsv("id,time\n1,2.5\n2,fast\n3,nan\n", "trials.csv");
  EXPECT_TRUE(throwsWithMessage([&] { t.numericColumn("time"); }, {"trials.csv:3", "column 'time'", "'fast' is not a number"}));
  EXPECT_TRUE(throwsWithMessage([&] { t.number(2, 1); }, {"trials.csv:4", "'nan' is not a number"}));
  EXPECT_TRUE(throwsWithMessage([&] { t.columnIndex("speed"); }, {"no column 'speed'", "columns: id, time"}));
}

TEST(Table, ProgrammaticColumnsRoundTripDoubles) {
  // The study adapter builds tables from columns; doubles must survive bit for bit.
  Table t("study.db", {});
  const std::vector<double> v = {0.1, 1.0 / 3.0, 1e-300, -123456789.123456789};
  t.addNumericColumn("x", v);
  t.addTextColumn("g", {"a", "b", "a", "b"});
  ASSERT_EQ(t.rowCount(), 4u);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(t.number(i, 0), v[i]);
  EXPECT_TRUE(throwsWithMessage([&] { t.addTextColumn("h", {"a"}); }, {"has 1 values", "4 rows"}));
}

TEST(Factor, LevelsOrderedLikeR) {
  // Numeric labels sort numerically (R sorts a numeric column's values), others by byte value.
  const Table t = parseCsv("g,h\n10,b\n2,a\n10,B\n1,a\n", "f.csv");
  const Factor g = makeFactor(t, "g");
  EXPECT_EQ(g.levels, (std::vector<std::string>{"1", "2", "10"}));
  EXPECT_EQ(g.codes, (std::vector<std::size_t>{2, 1, 2, 0}));
  const Factor h = makeFactor(t, "h");
  EXPECT_EQ(h.levels, (std::vector<std::string>{"B", "a", "b"}));
  const Table one = parseCsv("g\nx\nx\n", "one.csv");
  EXPECT_TRUE(throwsWithMessage([&] { requireLevelCount(makeFactor(one, "g"), 2, 2, "a t-test"); },
                                {"factor 'g' has only one level ('x')", "at least 2"}));
}

}  // namespace
}  // namespace tlab::analysis
