// tlab stimuli: render a stimulus set (scenes × styles × views × probe sets) to labelled PNGs,
// manifest.json and a PDF booklet. Also `tlab bench integrate` (registered by cmd_bench.cpp):
// integrator error vs. run time.
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "renderer/image/image.hpp"
#include "stimuli/bench/integrator_benchmark.hpp"

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
  render::writeFileAtomically(csvPath, std::vector<std::uint8_t>(csv.begin(), csv.end()));
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
  (void)app;
}

}  // namespace tlab::app
