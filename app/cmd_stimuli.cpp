// tlab stimuli: render a stimulus set (scenes × styles × views × probe sets) to labelled PNGs,
// manifest.json and a PDF booklet. Also `tlab bench integrate` (registered by cmd_bench.cpp):
// integrator error vs. run time.
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/build_revision.hpp"
#include "app/commands.hpp"
#include "app/style_file_check.hpp"
#include "app/scene_options.hpp"
#include "core/image.hpp"
#include "stimuli/bench/integrator_benchmark.hpp"
#include "stimuli/sets/probe_source.hpp"
#include "stimuli/sets/stimulus_set_file.hpp"
#include "stimuli/sets/stimulus_set_renderer.hpp"
#include "tasks/answer_form.hpp"
#include "tasks/question_json.hpp"
#include "tasks/task_registry.hpp"

namespace tlab::app {

namespace {

struct IntegrateBenchOptions {
  bool json = false;
  bool quick = false;
  int particles = 8;
  int repeats = 3;
  std::string out = "out/bench-integrate";
};

void runIntegrateBench(const IntegrateBenchOptions& o) {
  const auto rows = stimuli::runIntegratorBenchmark({o.particles, o.repeats, o.quick});
  std::filesystem::create_directories(o.out);
  const std::string csvPath = (std::filesystem::path(o.out) / "integrate.csv").string();
  const std::string svgPath = (std::filesystem::path(o.out) / "integrate.svg").string();
  const std::string csv = stimuli::integratorBenchmarkCsv(rows);
  core::writeFileAtomically(csvPath, std::vector<std::uint8_t>(csv.begin(), csv.end()));
  stimuli::writeIntegratorBenchmarkSvg(rows, svgPath);
  if (o.json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& r : rows)
      j.push_back({{"field", r.field}, {"integrator", r.integrator}, {"setting", r.setting}, {"reference", r.reference},
                   {"error", std::isfinite(r.error) ? nlohmann::json(r.error) : nlohmann::json("inf")},
                   {"microseconds_per_particle", r.microseconds}, {"steps_per_particle", r.steps}});
    std::cout << nlohmann::json{{"rows", j}, {"csv", csvPath}, {"svg", svgPath}}.dump(2) << "\n";
  } else {
    std::cout << "tlab bench integrate: " << o.particles << " particles per field, median of " << o.repeats << " runs\n"
              << stimuli::integratorBenchmarkTable(rows) << "wrote " << csvPath << " and " << svgPath << "\n";
  }
}

// The hook between stimuli and tasks: the tasks' questions with their exact ground truth, plus the
// stimuli library's own labelled points ("points").
class TaskProbeSource final : public stimuli::ProbeSource {
 public:
  std::vector<std::string> taskNames() const override {
    std::vector<std::string> names = points_.taskNames();
    for (const auto& n : tasks::taskNames()) names.push_back(n);
    return names;
  }

  std::vector<stimuli::ProbeQuestion> probe(const stimuli::ProbeView& view, const stimuli::ProbeSetSpec& spec) const override {
    if (spec.task == "points") return points_.probe(view, spec);
    const auto task = tasks::makeTask(spec.task);
    const tasks::ProbeRequest request{view.scene, view.camera, view.width, view.height, spec.count, spec.seed, task->settings(spec.settings)};
    std::vector<stimuli::ProbeQuestion> out;
    for (const auto& q : task->probe(request)) {
      stimuli::ProbeQuestion p;
      p.text = q.text;
      const auto field = tasks::answerForm(q).bookletField();
      p.answerFormat = field ? *field : std::string(tasks::answerFormat(q.answerKind)) + "; answer it in the window or the browser";
      p.printable = field.has_value();
      p.groundTruth = tasks::toJson(q);
      for (const auto& point : q.points) p.marks.push_back({point.label, point.role, point.world, point.pixel});
      out.push_back(std::move(p));
    }
    return out;
  }

 private:
  stimuli::SurfacePointProbes points_;
};

struct StimuliOptions {
  std::string setFile;
  std::string out;
  int jobs = 1;
  bool quiet = false;
};

void runStimuli(const StimuliOptions& o) {
  const stimuli::StimulusSetSpec spec = stimuli::readStimulusSetFile(o.setFile);
  std::vector<std::string> styles;
  for (const auto& st : spec.styles) styles.push_back(st.name);
  compileStyleFiles(styles);  // a broken style file: one line, before any picture
  const TaskProbeSource probes;
  const stimuli::StimulusSetRenderer renderer(sceneCatalog(), probes);
  const auto result = renderer.render(spec, {o.out, o.jobs, !o.quiet, versionString()});
  std::cout << "tlab stimuli: " << result.stimuli.size() << " images of '" << spec.name << "' in " << o.out << "; " << result.manifestPath
            << (result.bookletPath.empty() ? std::string() : ", " + result.bookletPath) << "\n";
}

}  // namespace

void addIntegrateBench(CLI::App& bench) {
  auto o = std::make_shared<IntegrateBenchOptions>();
  auto* cmd = bench.add_subcommand("integrate", "Particle integrators (RK4, Dormand-Prince, Rosenbrock4): error vs. run time per tolerance");
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->add_flag("--quick", o->quick, "fewer steps and tolerances");
  cmd->add_option("--particles", o->particles, "particles per field")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--repeats", o->repeats, "timed runs per setting (median)")->capture_default_str()->check(CLI::Range(1, 100));
  cmd->add_option("--out", o->out, "folder for integrate.csv and integrate.svg")->capture_default_str();
  cmd->callback([o] { runIntegrateBench(*o); });
}

void addStimuliCommand(CLI::App& app) {
  auto o = std::make_shared<StimuliOptions>();
  auto* cmd = app.add_subcommand("stimuli", "Render a stimulus set (scenes x styles x views x probe sets) to labelled PNGs, manifest.json and a PDF booklet");
  cmd->add_option("set", o->setFile, "stimulus-set file (TOML; see examples/stimulus-sets/)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--out", o->out, "output folder")->required();
  cmd->add_option("--jobs", o->jobs, "worker threads, each with its own GL context (output is identical for any value)")
      ->capture_default_str()->check(CLI::Range(1, 64));
  cmd->add_flag("--quiet", o->quiet, "no progress bar");
  cmd->callback([o] { runStimuli(*o); });
}

}  // namespace tlab::app
