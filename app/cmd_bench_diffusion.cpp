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

void runDiffusionBench(const DiffusionBenchOptions& o) {
  const auto [w, h] = parseSize(o.size);
  const auto context = gpu::createHeadlessContext();
  bench::DiffusionFrame frame(render::loadScene(o.scene, sceneCatalog()), w, h);
  const auto T = o.time;
  const std::vector<bench::DiffusionRun> runs = bench::measureDiffusionSchemes(frame, T);

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
  const auto seriesOf = [](const bench::DiffusionRun& r) {
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
