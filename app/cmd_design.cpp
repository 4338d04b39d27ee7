// tlab design EXPERIMENT.toml [--db study.db]: the experiment's design — counterbalancing, the
// participant slot → block order table, trials per participant — and, with --db, who holds which
// slot (dropped-out slots are re-assigned to the next newcomer). Then, unless --quick, the checks
// that need the stimuli: every trial of one balanced cycle of slots is prepared headless (into a
// temporary folder, removed again), so a task setting no probe can meet or a training stimulus
// shown again in a test fails here with file:line, not at the first participant's start.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "analysis/text_table.hpp"
#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "stimuli/sets/progress_bar.hpp"
#include "app/style_file_check.hpp"
#include "study/design/counterbalancing.hpp"
#include "study/design/experiment_file.hpp"
#include "study/design/session_plan.hpp"
#include "study/run/plan_checks.hpp"
#include "study/run/stimulus_library.hpp"
#include "study/run/text_painter.hpp"
#include "study/store/open_store.hpp"

namespace tlab::app {

namespace {

struct DesignOptions {
  std::string experiment;
  std::string db;
  int participants = 0;
  bool quick = false;
};

// A temporary folder, removed with everything in it when this goes out of scope.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~TemporaryFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

// Every trial of one balanced cycle of slots prepared headless: the probes of each task can be
// found, and no training stimulus is a test stimulus (study/run/plan_checks.hpp).
void checkStimuliOfPlans(const study::Experiment& e, const study::Design& design, int participants) {
  const int slots = study::slotsOfOneCycle(design, participants);
  const std::size_t trials = study::plannedTrialCount(e, design, slots);
  std::printf("checking the stimuli and probes of %zu planned trials of %d slot%s (rendering headless; --quick skips this) ...\n", trials,
              slots, slots == 1 ? "" : "s");
  std::fflush(stdout);
  const auto context = gpu::createHeadlessContext();
  study::TextPainter painter;
  const TemporaryFolder folder("tlab-design-" + e.id);
  study::StimulusLibrary stimuli(folder.path(), sceneCatalog(), painter);
  {
    stimuli::ProgressBar bar("stimuli", trials);
    study::checkPreparedPlans(e, design, stimuli, slots, [&] { bar.advance(); });
  }
  std::printf("every planned trial of %d slot%s prepared: probes found, no training stimulus shown in a test trial\n", slots,
              slots == 1 ? "" : "s");
}

std::string blockTasks(const study::SessionPlan& plan, int block) {
  std::string text;
  std::string last;
  for (const auto& t : plan.trials) {
    if (t.block != block || t.phase != study::Phase::Test || t.taskId == last) continue;
    last = t.taskId;
    text += (text.empty() ? "" : "+") + t.taskId;
  }
  return text;
}

void run(const DesignOptions& o) {
  const study::Experiment e = study::readExperimentFile(o.experiment);
  // A language without a shipped translation (or one lacking a key): what participants would see in English.
  for (const auto& key : e.texts.untranslated())
    std::fprintf(stderr, "warning: %s = \"%s\": text.%s has no text in this language; participants see the English \"%s\" (set it in [text])\n",
                 e.languageSource.c_str(), e.texts.language().c_str(), key.c_str(), e.texts.text(key).c_str());
  const auto images = checkExperimentOnGl(e);  // a broken style file or a misaligned image: one line
  const study::Design design = study::makeDesign(e);
  const int participants = o.participants > 0 ? o.participants : e.participants;
  std::printf("experiment %s: %s\n", e.id.c_str(), e.title.c_str());
  for (const auto& u : e.styleFiles) std::printf("style file %s: sha256 %s\n", u.written.c_str(), u.sha256.c_str());
  for (const auto& a : images)
    std::printf("images %s: aligned with %s (IoU %.4f), sha256 %s\n", a.image.c_str(), a.scene.c_str(), a.iou, a.sha256.c_str());
  std::printf("counterbalancing %s: %zu order rows x %zu between cells, %zu blocks per participant\n",
              study::counterbalancingName(e.counterbalancing), design.rowCount(), design.betweenCellCount(), design.blocksPerRow());
  const std::size_t multiple = design.balancedMultiple();
  std::printf("participants %d: %s (balanced for multiples of %zu)\n", participants,
              participants % int(multiple) == 0 ? "balanced" : "NOT balanced", multiple);

  analysis::TextTable table;
  table.caption = "Assignment of participant slots";
  table.header = {"slot", "row", "cell"};
  for (std::size_t b = 1; b <= design.blocksPerRow(); ++b) table.header.push_back("block " + std::to_string(b));
  table.header.push_back("records");
  for (int slot = 0; slot < participants; ++slot) {
    const study::SessionPlan plan = study::makeSessionPlan(e, design, slot);
    std::vector<std::string> row = {std::to_string(slot), std::to_string(plan.design.row), std::to_string(plan.design.betweenCell)};
    int tests = 0;
    for (const auto& t : plan.trials) tests += t.phase == study::Phase::Test ? 1 : 0;
    for (std::size_t b = 0; b < plan.design.blocks.size(); ++b)
      row.push_back(design.describe(plan.design.blocks[b]) + " [" + blockTasks(plan, int(b) + 1) + "]");
    row.push_back(std::to_string(tests) + (plan.trials.size() > std::size_t(tests) ? " +" + std::to_string(plan.trials.size() - tests) + " training" : ""));
    table.rows.push_back(std::move(row));
  }
  std::fputs(analysis::renderPlainText(table).c_str(), stdout);
  int total = 0;
  for (int slot = 0; slot < participants; ++slot)
    for (const auto& t : study::makeSessionPlan(e, design, slot).trials) total += t.phase == study::Phase::Test ? 1 : 0;
  std::printf("test records in total: %d\n", total);
  if (!o.quick) checkStimuliOfPlans(e, design, participants);

  if (o.db.empty()) return;
  const auto storeOwner = study::openStore(o.db, study::OpenMode::Read);
  study::Store& store = *storeOwner;
  if (!store.findExperiment(e.id)) {
    std::printf("%s: no participant of experiment '%s' yet\n", o.db.c_str(), e.id.c_str());
    return;
  }
  analysis::TextTable held;
  held.caption = "Slots in " + o.db;
  held.header = {"slot", "row", "participant", "status"};
  for (const auto& a : store.assignments(e.id))
    held.rows.push_back({std::to_string(a.slot), std::to_string(a.row), a.participant, a.status});
  std::fputs(analysis::renderPlainText(held).c_str(), stdout);
}

}  // namespace

void addDesignCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("design", "Print an experiment's counterbalanced design and participant assignment table");
  auto o = std::make_shared<DesignOptions>();
  cmd->add_option("experiment", o->experiment, "experiment file (TOML)")->required();
  cmd->add_option("--db", o->db, "also list who holds which slot in this study database");
  cmd->add_option("--participants", o->participants, "number of slots to list (default: the experiment's participants)");
  cmd->add_flag("--quick", o->quick, "skip preparing the stimuli of the plans (probe feasibility, training vs. test stimuli)");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
