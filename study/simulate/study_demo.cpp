#include "study/simulate/study_demo.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

#include "analysis/report_html.hpp"
#include "core/image.hpp"
#include "stimuli/sets/progress_bar.hpp"
#include "study/design/counterbalancing.hpp"
#include "study/design/example_experiments.hpp"
#include "study/design/experiment_file.hpp"
#include "study/design/session_plan.hpp"
#include "study/store/open_store.hpp"
#include "study/design/stimulus_size.hpp"
#include "study/run/stimulus_library.hpp"
#include "study/simulate/study_simulation.hpp"
#include "study/store/study_table.hpp"
#include "study/run/text_painter.hpp"

namespace tlab::study {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void writeText(const fs::path& path, const std::string& text) {
  core::writeFileAtomically(path.string(), std::vector<std::uint8_t>(text.begin(), text.end()));
}

// An area-averaged copy at most `maxSide` pixels on its longer side (for the report's gallery).
Canvas thumbnail(const Canvas& source, int maxSide) {
  const double scale = std::min(1.0, double(maxSide) / std::max(source.width(), source.height()));
  const int w = std::max(1, int(source.width() * scale)), h = std::max(1, int(source.height() * scale));
  Canvas out(w, h);
  const auto& in = source.rgba();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int x0 = x * source.width() / w, x1 = std::max(x0 + 1, (x + 1) * source.width() / w);
      const int y0 = y * source.height() / h, y1 = std::max(y0 + 1, (y + 1) * source.height() / h);
      double sum[4] = {0, 0, 0, 0};
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx)
          for (int c = 0; c < 4; ++c) sum[c] += in[(std::size_t(sy) * source.width() + sx) * 4 + c];
      const double n = double(x1 - x0) * (y1 - y0);
      out.blend(x, y, Rgba{std::uint8_t(sum[0] / n + 0.5), std::uint8_t(sum[1] / n + 0.5), std::uint8_t(sum[2] / n + 0.5), 255}, 255);
    }
  return out;
}

std::string pngBytes(const Canvas& canvas) {
  const auto bytes = core::encodePng(canvas.toImage());
  return std::string(bytes.begin(), bytes.end());
}

// Every participant slot's plan, prepared once per planned trial (renders and probes are cached by
// the library); returns the first question's stimulus of every test trial for the gallery.
struct Prepared {
  int stimuli = 0;
  std::vector<analysis::PageImage> gallery;
};

Prepared prepareAll(const Experiment& experiment, int participants, StimulusLibrary& stimuli, bool bars) {
  const Design design = makeDesign(experiment);
  std::vector<PlannedTrial> all;
  for (int slot = 0; slot < participants; ++slot) {
    auto plan = makeSessionPlan(experiment, design, slot);
    all.insert(all.end(), plan.trials.begin(), plan.trials.end());
  }
  Prepared out;
  std::set<std::string> written, shown;
  stimuli::ProgressBar bar("stimuli", all.size(), bars);
  for (const auto& trial : all) {
    const PreparedTrial p = stimuli.prepare(trial);
    if (written.insert(p.stimulusSha256).second) ++out.stimuli;
    const std::string key = trial.stimulus.text() + " | " + trial.taskId;
    if (trial.phase == Phase::Test && shown.insert(key).second)
      out.gallery.push_back({trial.taskId + ": " + trial.condition, "image/png", pngBytes(thumbnail(*p.stimulus, 240))});
    bar.advance();
  }
  return out;
}

// The dependent variable's mean per task (columns) and level of `factor` (rows), from the records.
analysis::TextTable summaryTable(Store& store, const StoredExperiment& stored, const AnalysisSpec& spec) {
  const std::string dv = spec.dependentVariables.front();
  const std::string factor = !spec.within.empty() ? spec.within.front() : !spec.between.empty() ? spec.between.front() : "";
  AnalysisSpec all = spec;
  all.tasks.clear();
  const analysis::Table table = analysisTable(store, stored, all, dv);
  const auto values = table.numericColumn(dv);
  const auto tasks = table.textColumn("task");
  const auto levels = factor.empty() ? std::vector<std::string>(values.size(), "all") : table.textColumn(factor);
  bool binary = true;
  for (const double v : values) binary = binary && (v == 0.0 || v == 1.0);

  std::vector<std::string> taskOrder, levelOrder;
  for (const auto& t : stored.experiment.tasks) taskOrder.push_back(t.id);
  if (const Factor* f = stored.experiment.factor(factor))
    for (const auto& l : f->levels) levelOrder.push_back(l.name);
  if (levelOrder.empty()) levelOrder = {"all"};
  std::map<std::pair<std::string, std::string>, std::pair<double, int>> cells;  // (level, task) → (sum, n)
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (const auto& t : {tasks[i], std::string("all tasks")}) {
      auto& c = cells[{levels[i], t}];
      c.first += values[i];
      c.second += 1;
    }
  }
  taskOrder.push_back("all tasks");
  analysis::TextTable out;
  out.caption = (binary ? "Percentage " : "Mean ") + dv + " by task and " + (factor.empty() ? "condition" : factor) +
                (binary ? " (test records; missing answers count as wrong)" : " (test records with a value)");
  out.header = {factor.empty() ? "condition" : factor};
  for (const auto& t : taskOrder) out.header.push_back(t);
  for (const auto& level : levelOrder) {
    std::vector<std::string> row = {level};
    for (const auto& t : taskOrder) {
      const auto found = cells.find({level, t});
      char text[64] = "-";
      if (found != cells.end() && found->second.second > 0) {
        const double mean = found->second.first / found->second.second;
        if (binary)
          std::snprintf(text, sizeof text, "%.1f %% (n=%d)", 100.0 * mean, found->second.second);
        else
          std::snprintf(text, sizeof text, "%.3g (n=%d)", mean, found->second.second);
      }
      row.push_back(text);
    }
    out.rows.push_back(std::move(row));
  }
  return out;
}

// The demo's files in the output folder, which must not hold a study already.
DemoResult demoFiles(const DemoOptions& o) {
  const fs::path dir(o.outDirectory);
  DemoResult result;
  result.databasePath = (dir / "study.db").string();
  result.reportPath = (dir / "report.html").string();
  result.experimentPath = (dir / o.example).string();
  if (fs::exists(result.databasePath))
    throw std::runtime_error(result.databasePath + " already holds a study; the demo never overwrites logged data - use a new --out folder");
  fs::create_directories(dir);
  return result;
}

// The example experiment (with the stimulus size asked for) written next to the database and parsed.
Experiment writeExperiment(const DemoOptions& o, DemoResult& result) {
  std::string text(exampleExperimentText(o.example));
  if (!o.stimulusSize.empty()) text = withStimulusSize(text, o.stimulusSize);
  writeText(result.experimentPath, text);
  const Experiment experiment = parseExperiment(text, result.experimentPath);
  result.participants = o.participants > 0 ? o.participants : experiment.participants;
  return experiment;
}

// Every participant simulated into a new database.
void simulateParticipants(const DemoOptions& o, const Experiment& experiment, StimulusLibrary& stimuli, DemoResult& result) {
  const auto storeOwner = openStore(result.databasePath);
  Store& store = *storeOwner;
  stimuli::ProgressBar bar("participants", std::size_t(result.participants), o.progressBars);
  SimulationOptions s;
  s.participants = result.participants;
  s.tlabVersion = o.tlabVersion;
  s.log = [&](const std::string&) { bar.advance(); };
  const SimulationResult r = simulateStudy(experiment, store, stimuli, s);
  result.trialsAnswered = r.trialsAnswered;
}

// The planned analyses of the stored records, and the HTML report: the stimulus gallery, the
// summary table of the first analysis and every analysis' report.
void writeReport(const DemoOptions& o, const Experiment& experiment, std::vector<analysis::PageImage> gallery,
                 DemoResult& result) {
  const auto storeOwner = openStore(result.databasePath, OpenMode::Read);
  Store& store = *storeOwner;
  const StoredExperiment stored = storedExperiment(store);
  result.analyses = analyzeStudy(store, stored);
  analysis::ReportPage page;
  page.title = experiment.title;
  page.paragraphs = {
      "Generated by tlab demo (tlab " + o.tlabVersion + ") from " + o.example + ": " + std::to_string(result.participants) +
          " simulated participants, " + std::to_string(result.trialsAnswered) + " records in study.db; stimuli in " +
          fs::path(result.stimulusDirectory).filename().string() + "/ (content-addressed by SHA-256).",
      "Every stimulus below is the first question of a test trial as the participants saw it (marks and labels on the "
      "rendering); the ground truth of every question is computed from the geometry and stored with the trial."};
  page.images = std::move(gallery);
  if (!experiment.analyses.empty()) {
    result.summary = summaryTable(store, stored, experiment.analyses.front());
    page.tables.push_back(result.summary);
  }
  for (const auto& a : result.analyses) page.reports.push_back(a.report);
  writeText(result.reportPath, analysis::renderHtml(page));
}

}  // namespace

DemoResult runDemo(const DemoOptions& o, const std::vector<render::BuiltinSceneSpec>& catalog) {
  const auto say = [&](const std::string& line) {
    if (o.log) o.log(line);
  };
  DemoResult result = demoFiles(o);
  const Experiment experiment = writeExperiment(o, result);
  say("experiment " + experiment.id + ": " + experiment.title + " -> " + result.experimentPath);

  TextPainter painter;
  result.stimulusDirectory = stimulusDirectoryFor(result.databasePath);
  StimulusLibrary stimuli(result.stimulusDirectory, catalog, painter);
  auto start = Clock::now();
  Prepared prepared = prepareAll(experiment, result.participants, stimuli, o.progressBars);
  result.prepareSeconds = secondsSince(start);
  result.stimuli = prepared.stimuli;
  char line[256];
  std::snprintf(line, sizeof line, "stimuli: %d marked stimuli with ground truth in %s (%.1f s)", result.stimuli,
                result.stimulusDirectory.c_str(), result.prepareSeconds);
  say(line);

  start = Clock::now();
  simulateParticipants(o, experiment, stimuli, result);
  result.simulateSeconds = secondsSince(start);
  std::snprintf(line, sizeof line, "simulated %d participants, %d records in %s (%.1f s)", result.participants, result.trialsAnswered,
                result.databasePath.c_str(), result.simulateSeconds);
  say(line);

  start = Clock::now();
  writeReport(o, experiment, std::move(prepared.gallery), result);
  result.analyzeSeconds = secondsSince(start);
  std::snprintf(line, sizeof line, "analysis: %zu planned analyses -> %s (%.1f s)", result.analyses.size(), result.reportPath.c_str(),
                result.analyzeSeconds);
  say(line);
  return result;
}

}  // namespace tlab::study
