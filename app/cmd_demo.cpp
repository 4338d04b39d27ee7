// tlab demo [--out DIR] [--elmqvist] [--participants N] [--size WxH]: the README's main command —
// the Carnecky 2013 replication (or, with --elmqvist, the Elmqvist design) end to end: stimuli with
// ground truth, simulated participants through the counterbalanced design into DIR/study.db, the
// planned analysis into DIR/report.html, and a summary table on the terminal.
#include <cstdio>
#include <memory>

#include "analysis/text_table.hpp"
#include "app/analysis_text.hpp"
#include "app/build_revision.hpp"
#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "study/simulate/study_demo.hpp"

namespace tlab::app {

namespace {

struct DemoOptions {
  std::string out = "out/demo";
  bool elmqvist = false;
  int participants = 0;
  std::string size;
};

void run(const DemoOptions& o) {
  if (o.participants < 0) throw std::invalid_argument("--participants: must be >= 1");
  if (!o.size.empty()) parseSize(o.size);  // a clear error before any work
  study::DemoOptions d;
  d.example = o.elmqvist ? "elmqvist.toml" : "carnecky2013.toml";
  d.outDirectory = o.out;
  d.participants = o.participants;
  d.stimulusSize = o.size;
  d.tlabVersion = versionString();
  d.log = [](const std::string& line) {
    std::printf("demo: %s\n", line.c_str());
    std::fflush(stdout);
  };
  const auto context = gpu::createHeadlessContext();
  const study::DemoResult r = study::runDemo(d, sceneCatalog());
  std::printf("\n");
  if (!r.summary.rows.empty()) std::fputs(analysis::renderPlainText(r.summary).c_str(), stdout);
  for (const auto& a : r.analyses) std::fputs(analysisText(a).c_str(), stdout);
  std::printf("\nreport: %s\ndatabase: %s (tlab export %s --csv DIR for R or pandas)\n", r.reportPath.c_str(), r.databasePath.c_str(),
              r.databasePath.c_str());
  std::printf("time: stimuli %.1f s, participants %.1f s, analysis %.1f s\n", r.prepareSeconds, r.simulateSeconds, r.analyzeSeconds);
}

}  // namespace

void addDemoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("demo", "Run a whole study end to end: stimuli, simulated participants, database, analysis and report");
  auto o = std::make_shared<DemoOptions>();
  cmd->add_option("--out", o->out, "output folder (must not hold a study.db yet)")->capture_default_str();
  cmd->add_flag("--elmqvist", o->elmqvist, "run the Elmqvist dynamic-transparency design instead of Carnecky 2013");
  cmd->add_option("--participants", o->participants, "simulated participants (default: the experiment's own number)");
  cmd->add_option("--size", o->size, "stimulus size WxH instead of the experiment's (a reduced run)");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
