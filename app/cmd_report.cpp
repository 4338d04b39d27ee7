// tlab report FILE.csv --dv COL [--within A[,B] --subject S] [--between A] -o report.html
// [--markdown report.md]: an HTML (and optionally Markdown) report with design, descriptives,
// outlier screening, ANOVA, two-condition/rank tests and plots.
// tlab report study.db -o report.html [--replays]: the same for a study database, following the
// analysis plan of the experiment file stored in it: one page with a section per [[analysis]] (and
// one Markdown file when asked), every file written named on its own line. --replays renders every
// interactive trial's logged frames again (as tlab replay --html does) into REPORT-replays/ beside
// the report, and the report's table of interactive trials links each page with its check.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "analysis/analysis_error.hpp"
#include "analysis/csv_reader.hpp"
#include "analysis/report.hpp"
#include "analysis/report_html.hpp"
#include "analysis/report_markdown.hpp"
#include "app/build_revision.hpp"
#include "app/commands.hpp"
#include "study/analyze/study_analysis.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "study/analyze/replay_listing.hpp"
#include "study/analyze/study_record_tables.hpp"
#include "study/replay/replay_outputs.hpp"
#include "study/replay/trial_replay.hpp"
#include "study/store/open_store.hpp"

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
  bool poolVersions = false;
  bool replays = false;
};

// Creates the folder a report goes into (as export does), with one plain line if it cannot.
void createParentFolder(const std::filesystem::path& path) {
  const std::filesystem::path parent = path.parent_path();
  if (parent.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(parent, error);
  if (error)
    throw an::AnalysisError(parent.string() + ": cannot create the folder for " + path.filename().string() + " (" +
                            error.message() + "); choose another -o path");
}

void writeFile(const std::filesystem::path& path, const std::string& content) {
  createParentFolder(path);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw an::AnalysisError(path.string() + ": cannot open for writing");
  out << content;
  if (!out) throw an::AnalysisError(path.string() + ": write failed");
}

void writeReport(const an::Report& report, const std::string& output, const std::string& markdown) {
  writeFile(output, an::renderHtml(report));
  std::cout << "wrote " << output << "\n";
  if (!markdown.empty()) {
    const std::filesystem::path md(markdown);
    const an::MarkdownDocument doc = an::renderMarkdown(report, md.stem().string());
    writeFile(md, doc.text);
    for (const auto& figure : doc.figures) writeFile(md.parent_path() / figure.fileName, figure.svg);
    std::cout << "wrote " << markdown << " and " << doc.figures.size() << " figure files\n";
  }
}

// Every planned analysis of a study in one Markdown file; figure files get the analysis' number.
void writeMarkdown(const std::vector<an::Report>& reports, const std::string& markdown) {
  const std::filesystem::path md(markdown);
  std::string text;
  std::size_t figures = 0;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const std::string stem = md.stem().string() + (i == 0 ? "" : "-" + std::to_string(i + 1));
    const an::MarkdownDocument doc = an::renderMarkdown(reports[i], stem);
    text += (i == 0 ? "" : "\n") + doc.text;
    for (const auto& figure : doc.figures) writeFile(md.parent_path() / figure.fileName, figure.svg);
    figures += doc.figures.size();
  }
  writeFile(md, text);
  std::cout << "wrote " << markdown << " and " << figures << " figure files\n";
}

// Every interactive trial with logged frames replayed into REPORT-replays/ beside the report: its
// page (frames, inputs, timing, answer, the check of each frame) by participant and sequence.
study::ReplayLinks writeReplays(study::Store& store, const study::StoredExperiment& stored, const std::filesystem::path& report) {
  const auto trials = study::replayableTrials(store, stored.experiment.id);
  if (trials.empty()) {
    std::cout << "no interactive trial has frames logged: no replays to write\n";
    return {};
  }
  const std::string folderName = report.stem().string() + "-replays";
  const std::filesystem::path folder = report.parent_path() / folderName;
  const auto context = gpu::createHeadlessContext();
  const study::ReplayRenderer self{context->info().renderer, versionString()};
  study::ReplayLinks links;
  std::size_t frames = 0, identical = 0;
  for (const auto& t : trials) {
    const study::LoggedTrial trial = study::loadLoggedTrial(store, stored.experiment.id, t.participant, t.sequence);
    const std::string page = study::replayStem(t) + ".html";
    const study::ReplayCheck check = study::writeReplayPage(trial, sceneCatalog(), self, folder / page);
    links[{t.participant, t.sequence}] = {folderName + "/" + page, check.summary()};
    frames += check.frames.size();
    identical += std::size_t(check.identical());
  }
  std::cout << "wrote " << trials.size() << " replay " << (trials.size() == 1 ? "page" : "pages") << " to " << folder.string() << ": "
            << identical << " of " << frames << " frames identical\n";
  return links;
}

void runDatabase(const ReportOptions& o) {
  if (!o.dvs.empty() || !o.within.empty() || !o.between.empty() || !o.subject.empty())
    throw an::AnalysisError("a study database is reported by its experiment's analysis plan; --dv/--within/--between/--subject are for CSV files");
  const auto storeOwner = study::openStore(o.file, study::OpenMode::Read);
  study::Store& store = *storeOwner;
  const study::StoredExperiment stored = study::storedExperiment(store, "", o.poolVersions);
  const auto analyses = study::analyzeStudy(store, stored);
  if (analyses.empty()) throw an::AnalysisError(o.file + ": the experiment plans no [[analysis]]");
  an::ReportPage page;
  const std::string& id = stored.experiment.title.empty() ? stored.experiment.id : stored.experiment.title;
  page.title = !o.title.empty() ? o.title : id;
  createParentFolder(o.output);
  const study::ReplayLinks replays = o.replays ? writeReplays(store, stored, o.output) : study::ReplayLinks{};
  for (const auto& analysis : analyses) {
    an::Report report = analysis.report;
    study::appendStudyRecord(report, store, stored, replays);
    page.reports.push_back(std::move(report));
  }
  if (page.reports.size() == 1 && !o.title.empty()) page.reports.front().title = o.title;
  writeFile(o.output, page.reports.size() == 1 ? an::renderHtml(page.reports.front()) : an::renderHtml(page));
  std::cout << "wrote " << o.output << " (" << analyses.size() << " planned " << (analyses.size() == 1 ? "analysis" : "analyses") << ")\n";
  if (!o.markdown.empty()) writeMarkdown(page.reports, o.markdown);
}

void run(const ReportOptions& o) {
  if (std::filesystem::path(o.file).extension() == ".db" || study::isServerLocation(o.file)) return runDatabase(o);
  if (o.replays) throw an::AnalysisError("--replays renders the interactive trials of a study database; a CSV file has none");
  if (o.dvs.empty()) throw an::AnalysisError("--dv is required for a CSV file");
  if (!o.within.empty() && o.subject.empty())
    throw an::AnalysisError("--within needs --subject (the column naming the participant)");
  an::AnalysisPlan plan;
  plan.title = o.title.empty() ? "Analysis of " + std::filesystem::path(o.file).filename().string() : o.title;
  plan.dependentVariables = o.dvs;
  plan.between = o.between;
  plan.within = o.within;
  plan.subject = o.subject;
  plan.ssType = an::parseSumOfSquaresType(o.ssType);
  writeReport(an::makeReport(an::readCsvFile(o.file), plan), o.output, o.markdown);
}

}  // namespace

void addReportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("report", "Write an HTML (and Markdown) analysis report for a long-format CSV file or a study database");
  const auto options = std::make_shared<ReportOptions>();
  ReportOptions& o = *options;
  cmd->add_option("file", o.file, "Long-format CSV file (header row), or a study database (.db file or postgresql:// URL)")->required();
  cmd->add_option("--dv", o.dvs, "Dependent variable column(s), comma-separated (CSV files)")->delimiter(',');
  cmd->add_option("--between", o.between, "Between-subject factor column(s)")->delimiter(',');
  cmd->add_option("--within", o.within, "Within-subject factor column(s)")->delimiter(',');
  cmd->add_option("--subject", o.subject, "Subject column (required with --within)");
  cmd->add_option("-o,--output", o.output, "HTML output file")->required();
  cmd->add_option("--markdown", o.markdown, "Also write Markdown (figures as SVG files next to it)");
  cmd->add_option("--title", o.title, "Report title");
  cmd->add_flag("--pool-versions", o.poolVersions, "report data of experiment versions whose designs differ together (databases)");
  cmd->add_flag("--replays", o.replays,
                "render every interactive trial's logged frames again into REPORT-replays/ beside the report (as tlab replay --html "
                "does) and link each page, with its check, from the report (study databases)");
  cmd->add_option("--ss-type", o.ssType, "Sums of squares for unbalanced data: 2 or 3")->capture_default_str();
  cmd->callback([options] { run(*options); });
}

}  // namespace tlab::app
