// Report generation: a report over a small mixed design contains the design, descriptives, the
// ANOVA (same numbers as anova_test.cpp, from car::Anova), the rank tests and two SVG figures drawn
// by Cairo; HTML embeds them, Markdown links them.
#include "analysis/report.hpp"

#include "analysis/csv_reader.hpp"
#include "analysis/number_format.hpp"
#include "analysis/report_html.hpp"
#include "analysis/report_markdown.hpp"
#include "analysis/svg_plots.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;

Table mixedData() { return readCsvFile(std::string(TLAB_TEST_DATA) + "/analysis/mixed.csv"); }

AnalysisPlan mixedPlan() {
  return {.title = "Mixed design",
          .dependentVariables = {"y"},
          .between = {"g"},
          .within = {"time"},
          .subject = std::string("s")};
}

TEST(Report, MixedDesignHasEverySection) {
  const Report report = makeReport(mixedData(), mixedPlan());
  EXPECT_EQ(report.design.subjects, 9u);
  ASSERT_EQ(report.dependentVariables.size(), 1u);
  const auto& dv = report.dependentVariables[0];
  ASSERT_EQ(dv.cells.size(), 6u);  // 2 groups × 3 times
  EXPECT_EQ(dv.cells[0].label, "g=ctrl, time=t1");
  // ctrl at t1: subjects 1-4 have 10, 8, 12, 9 → mean 9.75.
  ASSERT_TRUE(dv.cells[0].stats.has_value());
  EXPECT_DOUBLE_EQ(dv.cells[0].stats->mean, 9.75);
  ASSERT_TRUE(dv.anova.has_value());
  EXPECT_TRUE(relativelyNear(dv.anova->effects[1].F, 78.3713124889596, 1e-10));  // car::Anova type II
  ASSERT_EQ(dv.comparisons.size(), 2u);  // Friedman on time (3 levels), Welch + Mann-Whitney on g
  EXPECT_TRUE(dv.comparisons[0].friedman.has_value());
  EXPECT_TRUE(dv.comparisons[1].tTest.has_value());
  EXPECT_TRUE(dv.comparisons[1].mannWhitney.has_value());
  ASSERT_EQ(dv.figures.size(), 2u);
  for (const auto& f : dv.figures) {
    EXPECT_NE(f.svg.find("<svg"), std::string::npos);
    EXPECT_NE(f.svg.find("</svg>"), std::string::npos);
    EXPECT_GT(f.svg.size(), 2000u);  // bars/boxes and glyphs were drawn
  }
}

TEST(Report, HtmlEmbedsFiguresAndMarkdownLinksThem) {
  const Report report = makeReport(mixedData(), mixedPlan());
  const std::string html = renderHtml(report);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<h1>Mixed design</h1>"), std::string::npos);
  EXPECT_NE(html.find("Descriptives of y per cell"), std::string::npos);
  EXPECT_NE(html.find("ANOVA (type II"), std::string::npos);
  EXPECT_NE(html.find("Mauchly"), std::string::npos);
  EXPECT_NE(html.find("Friedman"), std::string::npos);
  std::size_t images = 0;
  for (std::size_t at = html.find("data:image/svg+xml;base64,"); at != std::string::npos;
       at = html.find("data:image/svg+xml;base64,", at + 1))
    ++images;
  EXPECT_EQ(images, 2u);
  const MarkdownDocument md = renderMarkdown(report, "out");
  ASSERT_EQ(md.figures.size(), 2u);
  EXPECT_EQ(md.figures[0].fileName, "out_fig1.svg");
  EXPECT_NE(md.text.find("](out_fig2.svg)"), std::string::npos);
  EXPECT_NE(md.text.find("| effect | df1 | df2 |"), std::string::npos);
}

TEST(Report, BadCellsAreReportedNotFatal) {
  // A between group with one subject: its descriptives say n < 2, the ANOVA still runs.
  const Table t = parseCsv("g,y\na,1\na,2\na,4\nb,3\n", "small.csv");
  AnalysisPlan plan;
  plan.dependentVariables = {"y"};
  plan.between = {"g"};
  const Report report = makeReport(t, plan);
  const auto& dv = report.dependentVariables[0];
  EXPECT_FALSE(dv.cells[1].stats.has_value());
  EXPECT_NE(dv.cells[1].error.find("n = 1"), std::string::npos);
  EXPECT_TRUE(dv.anova.has_value());
  EXPECT_FALSE(dv.comparisons[0].error.empty());  // Welch needs n ≥ 2 per group
  EXPECT_NE(renderHtml(report).find("n = 1"), std::string::npos);
}

TEST(SvgPlots, NiceTicksAndBase64) {
  // Heckbert's nice numbers: [0, 67] → 0, 20, 40, 60, 80 (5 ticks of 2·10^1).
  EXPECT_EQ(niceTicks(0, 67, 5), (std::vector<double>{0, 20, 40, 60, 80}));
  // RFC 4648 test vectors.
  EXPECT_EQ(base64Encode("foob"), "Zm9vYg==");
  EXPECT_EQ(base64Encode("foobar"), "Zm9vYmFy");
}

}  // namespace
}  // namespace tlab::analysis
