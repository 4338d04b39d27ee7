// Report details a reader relies on: a proportion's bar chart ends at 1 (not at 1.5), each method
// note is printed once, and warnings (e.g. simulated data) come before everything else.
#include "analysis/report.hpp"
#include "analysis/report_html.hpp"
#include "analysis/report_markdown.hpp"
#include "analysis/svg_plots.hpp"
#include "analysis/text_table.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

TEST(ReportProportion, BarChartAxisEndsAtTheScalesCeiling) {
  BarChart chart;
  chart.categories = {"alpha", "smart"};
  chart.series = {{"", {0.9, 0.6}, {0.35, 0.4}}};  // mean + SD = 1.25 and 1.0
  EXPECT_GT(barChartTicks(chart).back(), 1.2);     // an unbounded scale runs past the bars
  chart.yFloor = 0.0;
  chart.yCeiling = 1.0;
  const auto ticks = barChartTicks(chart);
  EXPECT_DOUBLE_EQ(ticks.front(), 0.0);
  EXPECT_DOUBLE_EQ(ticks.back(), 1.0);
}

Table binaryData() {
  Table t("p.csv", {"s", "method", "correct", "rt"});
  std::size_t line = 1;
  const int correct[6][2] = {{1, 1}, {1, 0}, {1, 1}, {0, 1}, {1, 1}, {1, 1}};
  for (int s = 0; s < 6; ++s)
    for (int m = 0; m < 2; ++m)
      t.addRow({std::to_string(s), m ? "smart" : "alpha", std::to_string(correct[s][m]), std::to_string(2.5 + s + 0.25 * m)}, ++line);
  return t;
}

TEST(ReportProportion, ZeroOneVariablesArePlottedAsProportionsAndNotesComeOnce) {
  AnalysisPlan plan;
  plan.dependentVariables = {"correct", "rt"};
  plan.within = {"method"};
  plan.subject = "s";
  const Report r = makeReport(binaryData(), plan);
  ASSERT_EQ(r.dependentVariables.size(), 2u);
  EXPECT_TRUE(r.dependentVariables[0].proportion);
  EXPECT_FALSE(r.dependentVariables[1].proportion);
  plan.proportions = {"rt"};  // a plan may name one (e.g. a score in [0, 1])
  EXPECT_TRUE(makeReport(binaryData(), plan).dependentVariables[1].proportion);
  std::vector<std::string> notes = r.notes;
  std::sort(notes.begin(), notes.end());
  EXPECT_EQ(std::unique(notes.begin(), notes.end()), notes.end());
}

TEST(ReportProportion, WarningsComeFirstAndAppendicesLast) {
  AnalysisPlan plan;
  plan.dependentVariables = {"correct"};
  plan.within = {"method"};
  plan.subject = "s";
  Report r = makeReport(binaryData(), plan);
  r.warnings = {"SIMULATED DATA: not people"};
  r.appendices = {TextTable{"Stimuli shown", {"file"}, {{"a.png"}}}};
  const std::string html = renderHtml(r);
  EXPECT_LT(html.find("SIMULATED DATA: not people"), html.find("<table"));
  EXPECT_GT(html.find("Stimuli shown"), html.find("Box plots of correct"));
  const std::string md = renderMarkdown(r, "fig").text;
  EXPECT_LT(md.find("SIMULATED DATA: not people"), md.find("|"));
  EXPECT_NE(md.find("a.png"), std::string::npos);
}

TEST(ReportProportion, ACellWithALinkIsALinkInHtmlAndMarkdownAndPlainTextElsewhere) {
  TextTable t{"Replays", {"who", "page"}, {{"p<1>", "3 of 3 frames identical"}, {"p2", "not rendered"}}, {{"", "r/replay-p1.html"}}};
  EXPECT_EQ(cellLink(t, 0, 1), "r/replay-p1.html");
  EXPECT_EQ(cellLink(t, 0, 0), "");
  EXPECT_EQ(cellLink(t, 1, 1), "") << "a row beyond the links has none";
  const std::string html = renderHtmlTable(t);
  EXPECT_NE(html.find("<td><a href=\"r/replay-p1.html\">3 of 3 frames identical</a></td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>p&lt;1&gt;</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>not rendered</td>"), std::string::npos) << html;
  const std::string md = renderMarkdownTable(t);
  EXPECT_NE(md.find("| p<1> | [3 of 3 frames identical](r/replay-p1.html) |"), std::string::npos) << md;
  EXPECT_EQ(renderPlainText(t).find("replay-p1.html"), std::string::npos);
}

}  // namespace
}  // namespace tlab::analysis
