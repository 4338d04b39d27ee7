#pragma once
// StudyDemo: a whole study end to end, as `tlab demo` runs it — the example experiment file
// written to the output folder (optionally with a reduced stimulus size), every stimulus of every
// participant's plan rendered and probed once (with its exact ground truth), the simulated
// participants run through the counterbalanced design into DIR/study.db, the analysis plan run on
// the database, and one HTML page DIR/report.html with the stimuli, the per-task summary, the
// tests and the plots. Needs a current GL context.
#include <functional>
#include <string>
#include <vector>

#include "analysis/text_table.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "study/analyze/study_analysis.hpp"

namespace tlab::study {

struct DemoOptions {
  std::string example = "carnecky2013.toml";  // a file of examples/ (exampleExperimentText)
  std::string outDirectory = "out/demo";
  int participants = 0;       // 0: the experiment's own number
  std::string stimulusSize;   // "WxH" replaces the experiment's [stimulus] size (reduced runs); "" keeps it
  std::string tlabVersion = "unknown";
  bool progressBars = true;   // drawn only when stderr is a terminal
  std::function<void(const std::string&)> log;  // one line per step
};

struct DemoResult {
  std::string experimentPath, databasePath, reportPath, stimulusDirectory;
  int participants = 0;
  int stimuli = 0;        // distinct marked stimuli written
  int trialsAnswered = 0;
  double prepareSeconds = 0.0, simulateSeconds = 0.0, analyzeSeconds = 0.0;
  analysis::TextTable summary;  // dependent variable by task × first within factor
  std::vector<StudyAnalysis> analyses;
};

// Throws when DIR already holds a study database (a demo never overwrites logged data).
DemoResult runDemo(const DemoOptions& options, const std::vector<render::BuiltinSceneSpec>& catalog);

}  // namespace tlab::study
