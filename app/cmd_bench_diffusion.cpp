// tlab bench diffusion: error of the α field against run time for each diffusion scheme
// (explicit at its stability bound, sub-stepped, implicit with Jacobi sweeps), for both readings of
// Eq. 8's Laplacian (normalised: the default; sum), so a user can choose
// iterations by accuracy per millisecond (Carnecky Eq. 8; see ops/diffuse_alpha.comp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/svg_plots.hpp"
#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "bench/measure/diffusion_frame.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "core/image.hpp"
#include "renderer/ops/diffusion_solver.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/smart_style.hpp"

namespace tlab::app {

namespace {

struct DiffusionBenchOptions {
  std::string scene = "builtin:open-cylinders";
  std::string size = "256x256";
  double time = 20.0;  // diffusion time T = n·λα (the paper's default n = 20, λα = 1)
  std::string out = "out/bench";
  bool json = false;
};

struct Run {
  std::string laplacian;
  std::string scheme;
  std::string setting;
  int passes = 0;
  double ms = 0, maxError = 0, rmsError = 0;
};

// "1/4" for 0.25, "1" for 1: the λ of a run as the table prints it.
std::string fraction(double lambda) {
  if (lambda >= 1) return std::to_string(int(std::lround(lambda)));
  return "1/" + std::to_string(int(std::lround(1 / lambda)));
}

render::SmartSettings settingsFor(bool normalized, render::DiffusionScheme scheme, int steps, double lambda, int sweeps) {
  render::SmartSettings s;
  s.normalizedLaplacian = normalized;
  s.adaptiveAlpha = true;  // α varies with the layer count: something to diffuse
  s.s = 0.7;
  s.halos = false;
  s.silhouettes = false;  // time α alone
  s.scheme = scheme;
  s.iterations = steps;
  s.lambdaAlpha = lambda;
  s.jacobiSweeps = sweeps;
  return s;
}

void runDiffusionBench(const DiffusionBenchOptions& o) {
  const auto [w, h] = parseSize(o.size);
  const auto context = gpu::createHeadlessContext();
  bench::DiffusionFrame frame(render::loadScene(o.scene, sceneCatalog()), w, h);
  const auto T = o.time;
  std::vector<Run> runs;
  for (const bool normalized : {true, false}) {
    const std::string reading = normalized ? "normalized" : "sum";
    const double bound = normalized ? render::kExplicitStableLambdaNormalized : render::kExplicitStableLambdaSum;
    const auto with = [&](render::DiffusionScheme scheme, double lambda, int sweeps) {
      return settingsFor(normalized, scheme, static_cast<int>(std::lround(T / lambda)), lambda, sweeps);
    };
    // Reference: explicit steps 16 times finer than the reading's stability bound.
    double refMs = 0;
    const auto reference = frame.diffuse(with(render::DiffusionScheme::Explicit, bound / 16, 1), &refMs);
    const auto measure = [&](const std::string& scheme, const std::string& setting, const render::SmartSettings& s) {
      frame.diffuse(s, &refMs);  // warm-up (shader compilation)
      Run r{reading, scheme, setting};
      const auto alpha = frame.diffuse(s, &r.ms);
      r.passes = s.iterations * render::DiffusionSolver(frame.shaders, s).dispatchesPerStep();
      double sum = 0;
      for (std::size_t i = 0; i < alpha.size(); ++i) {
        const double e = std::fabs(double(alpha[i]) - reference[i]);
        r.maxError = std::max(r.maxError, e);
        sum += e * e;
      }
      r.rmsError = alpha.empty() ? 0 : std::sqrt(sum / double(alpha.size()));
      runs.push_back(r);
    };
    for (int m : {1, 2, 4, 8})  // explicit: the bound and finer
      measure("explicit", "lambda=" + fraction(bound / m), with(render::DiffusionScheme::Explicit, bound / m, 1));
    for (double lambda : {1.0, 2.0, 4.0})  // sub-stepped: the paper's λα = 1 and beyond
      if (lambda > bound) measure("substep", "lambda=" + std::to_string(int(lambda)), with(render::DiffusionScheme::Substep, lambda, 1));
    for (double lambda : {1.0, 4.0})
      for (int sweeps : {2, 5, 10, 20})
        measure("implicit", "lambda=" + std::to_string(int(lambda)) + " sweeps=" + std::to_string(sweeps),
                with(render::DiffusionScheme::Implicit, lambda, sweeps));
  }

  std::filesystem::create_directories(o.out);
  std::string csv = "laplacian,scheme,setting,passes,ms,max_error,rms_error\n";
  for (const auto& r : runs)
    csv += r.laplacian + "," + r.scheme + "," + r.setting + "," + std::to_string(r.passes) + "," + std::to_string(r.ms) + "," +
           std::to_string(r.maxError) + "," + std::to_string(r.rmsError) + "\n";
  const auto csvPath = (std::filesystem::path(o.out) / "diffusion.csv").string();
  const auto svgPath = (std::filesystem::path(o.out) / "diffusion.svg").string();
  core::writeFileAtomically(csvPath, std::vector<std::uint8_t>(csv.begin(), csv.end()));
  analysis::LinePlot plot;
  plot.title = "alpha diffusion to time " + std::to_string(int(T)) + ": error vs. run time";
  plot.xLabel = "solve time [ms]";
  plot.yLabel = "max |alpha - reference|";
  plot.logX = plot.logY = true;
  // One line per scheme, and per λ for the implicit runs (their sweeps vary along the line).
  const auto seriesOf = [](const Run& r) {
    return r.laplacian + " " + (r.scheme == "implicit" ? r.scheme + " " + r.setting.substr(0, r.setting.find(' ')) : r.scheme);
  };
  for (const auto& r : runs) {
    const std::string name = seriesOf(r);
    auto it = std::find_if(plot.series.begin(), plot.series.end(), [&](const auto& s) { return s.label == name; });
    if (it == plot.series.end()) it = plot.series.insert(plot.series.end(), analysis::LineSeries{name, {}, {}});
    it->x.push_back(r.ms);
    it->y.push_back(std::max(r.maxError, 1e-9));
  }
  const std::string svg = analysis::renderLinePlotSvg(plot);
  core::writeFileAtomically(svgPath, std::vector<std::uint8_t>(svg.begin(), svg.end()));
  if (o.json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& r : runs)
      j.push_back({{"laplacian", r.laplacian}, {"scheme", r.scheme}, {"setting", r.setting}, {"passes", r.passes}, {"ms", r.ms},
                   {"max_error", r.maxError}, {"rms_error", r.rmsError}});
    std::cout << nlohmann::json{{"scene", o.scene}, {"size", o.size}, {"fragments", frame.buffer->fragmentCount()},
                                {"time", T}, {"runs", j}}.dump(2) << "\n";
    return;
  }
  std::printf("tlab bench diffusion: %s at %s (%llu fragments), diffusion time T = n*lambda = %g;\n"
              "reference per reading of Eq. 8's Laplacian: explicit steps 16x finer than its stability bound\n"
              "(normalized: lambda <= 1; sum: lambda <= 1/4). Errors of alpha in [0, 1].\n",
              o.scene.c_str(), o.size.c_str(), static_cast<unsigned long long>(frame.buffer->fragmentCount()), T);
  std::printf("%-10s %-9s %-22s %7s %10s %12s %12s\n", "laplacian", "scheme", "setting", "passes", "ms", "max error", "rms error");
  for (const auto& r : runs)
    std::printf("%-10s %-9s %-22s %7d %10.1f %12.2e %12.2e\n", r.laplacian.c_str(), r.scheme.c_str(), r.setting.c_str(), r.passes, r.ms, r.maxError, r.rmsError);
  std::printf("wrote %s and %s\n", csvPath.c_str(), svgPath.c_str());
}

}  // namespace

void addDiffusionBench(CLI::App& bench) {
  auto o = std::make_shared<DiffusionBenchOptions>();
  auto* cmd = bench.add_subcommand("diffusion", "Error of the alpha field vs. run time for each diffusion scheme (CSV + SVG plot)");
  cmd->add_option("--scene", o->scene, "scene")->capture_default_str();
  cmd->add_option("--size", o->size, "image size WxH")->capture_default_str();
  cmd->add_option("--time", o->time, "diffusion time n*lambda_alpha")->capture_default_str()->check(CLI::Range(0.25, 1000.0));
  cmd->add_option("--out", o->out, "folder for diffusion.csv and diffusion.svg")->capture_default_str();
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->callback([o] { runDiffusionBench(*o); });
}

}  // namespace tlab::app
