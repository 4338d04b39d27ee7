// tlab report FILE.csv --dv COL [--within A[,B] --subject S] [--between A] -o report.html
// [--markdown report.md]: an HTML (and optionally Markdown) report with design, descriptives,
// outlier screening, ANOVA, two-condition/rank tests and plots.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "analysis/analysis_error.hpp"
#include "analysis/csv_reader.hpp"
#include "analysis/report.hpp"
#include "analysis/report_html.hpp"
#include "analysis/report_markdown.hpp"
#include "app/commands.hpp"

namespace tlab::app {

namespace {

namespace an = tlab::analysis;

struct ReportOptions {
  std::string file;
  std::vector<std::string> dvs;
  std::vector<std::string> between;
  std::vector<std::string> within;
  std::string subject;
  std::string output;
  std::string markdown;
  std::string title;
  std::string ssType = "2";
};

void writeFile(const std::filesystem::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw an::AnalysisError(path.string() + ": cannot open for writing");
  out << content;
  if (!out) throw an::AnalysisError(path.string() + ": write failed");
}

void run(const ReportOptions& o) {
  if (!o.within.empty() && o.subject.empty())
    throw an::AnalysisError("--within needs --subject (the column naming the participant)");
  an::AnalysisPlan plan;
  plan.title = o.title.empty() ? "Analysis of " + std::filesystem::path(o.file).filename().string() : o.title;
  plan.dependentVariables = o.dvs;
  plan.between = o.between;
  plan.within = o.within;
  plan.subject = o.subject;
  plan.ssType = an::parseSumOfSquaresType(o.ssType);
  const an::Report report = an::makeReport(an::readCsvFile(o.file), plan);
  writeFile(o.output, an::renderHtml(report));
  std::cout << "wrote " << o.output << "\n";
  if (!o.markdown.empty()) {
    const std::filesystem::path md(o.markdown);
    const an::MarkdownDocument doc = an::renderMarkdown(report, md.stem().string());
    writeFile(md, doc.text);
    for (const auto& figure : doc.figures) writeFile(md.parent_path() / figure.fileName, figure.svg);
    std::cout << "wrote " << o.markdown << " and " << doc.figures.size() << " SVG figures\n";
  }
}

}  // namespace

void addReportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("report", "Write an HTML (and Markdown) analysis report for a long-format CSV file");
  const auto options = std::make_shared<ReportOptions>();
  ReportOptions& o = *options;
  cmd->add_option("file", o.file, "Long-format CSV file (header row)")->required();
  cmd->add_option("--dv", o.dvs, "Dependent variable column(s), comma-separated")->required()->delimiter(',');
  cmd->add_option("--between", o.between, "Between-subject factor column(s)")->delimiter(',');
  cmd->add_option("--within", o.within, "Within-subject factor column(s)")->delimiter(',');
  cmd->add_option("--subject", o.subject, "Subject column (required with --within)");
  cmd->add_option("-o,--output", o.output, "HTML output file")->required();
  cmd->add_option("--markdown", o.markdown, "Also write Markdown (figures as SVG files next to it)");
  cmd->add_option("--title", o.title, "Report title");
  cmd->add_option("--ss-type", o.ssType, "Sums of squares for unbalanced data: 2 or 3")->capture_default_str();
  cmd->callback([options] { run(*options); });
}

}  // namespace tlab::app
