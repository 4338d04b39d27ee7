// tlab bench: speed measurements (never timed assertions in tests).
//   tlab bench render — the per-pass timing table of Carnecky Figs. 14-15 on the torus, with the
//   ratio to plain unsorted blending (the floor) and the R² of time vs. fragments; with --scene,
//   one scene in one or more styles (app/cmd_bench_scene.cpp).
#include <algorithm>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/bench_floor.hpp"
#include "app/bench_scene.hpp"
#include "app/commands.hpp"
#include "bench/measure/render_sweep.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"

namespace tlab::app {

namespace {

struct BenchRenderOptions {
  bool json = false;
  bool quick = false;
  std::string fill = "both";
  std::string style = "constant";
  int repeats = 3;
};

// Least-squares line through (x, y) and its coefficient of determination.
double rSquared(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / n, my += y[i] / n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0 && syy > 0 ? (sxy * sxy) / (sxx * syy) : 0.0;
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    if (end > start) out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::vector<render::FillMethod> benchFills(const BenchRenderOptions& o) {
  std::vector<render::FillMethod> fills;
  if (o.fill == "both" || o.fill == "scatter") fills.push_back(render::FillMethod::CountScatter);
  if (o.fill == "both" || o.fill == "list") fills.push_back(render::FillMethod::LinkedList);
  if (fills.empty()) throw std::invalid_argument("--fill must be scatter, list or both");
  return fills;
}

// The three sweeps (resolution, triangles, layers) for each fill method.
std::vector<bench::RenderSweepRow> runSweeps(const BenchRenderOptions& o, const std::vector<render::FillMethod>& fills) {
  const std::vector<int> sizes = o.quick ? std::vector<int>{128, 256, 512} : std::vector<int>{128, 256, 512, 1024, 2048};
  const std::vector<int> triangles = o.quick ? std::vector<int>{10000, 100000} : std::vector<int>{10000, 30000, 100000, 300000, 1000000};
  std::vector<bench::RenderSweepRow> rows;
  for (auto fill : fills) {
    for (int s : sizes) rows.push_back(bench::measureRenderSweep("resolution", "builtin:torus?triangles=100000", s, fill, o.style, o.repeats));
    for (int t : triangles)
      rows.push_back(bench::measureRenderSweep("triangles", "builtin:torus?triangles=" + std::to_string(t), o.quick ? 512 : 1024, fill,
                                                o.style, o.repeats));
    rows.push_back(bench::measureRenderSweep("layers", "builtin:quad-stack?n=16", 512, fill, o.style, o.repeats));
  }
  return rows;
}

// Columns: every pass that ran, in the order passes run (fill, sort, [connect, solve,] compose).
std::vector<std::string> passColumns(const std::vector<bench::RenderSweepRow>& rows) {
  std::vector<std::string> passNames;
  for (const auto& r : rows)
    for (const auto& p : r.passes)
      if (std::find(passNames.begin(), passNames.end(), p.first) == passNames.end()) passNames.push_back(p.first);
  return passNames;
}

void printTableHeader(const BenchRenderOptions& o, const std::vector<std::string>& passNames) {
  std::printf("tlab bench render: style %s, median of %d frames after a warm-up; ms per pass\n", o.style.c_str(), o.repeats);
  std::printf("%-10s %-8s %-36s %5s %9s %9s", "sweep", "fill", "scene", "size", "triangles", "fragments");
  for (const auto& n : passNames) std::printf(" %8s", n.c_str());
  std::printf(" %8s %9s %9s %7s\n", "total", "Mfrag/s", "unsorted", "ratio");
}

// One row as a JSON object (appended to j) or as a table line.
void reportRow(const BenchRenderOptions& o, const bench::RenderSweepRow& r, const std::vector<std::string>& passNames,
               nlohmann::json& j) {
  const auto get = [&](const std::string& n) {
    for (const auto& p : r.passes)
      if (p.first == n) return p.second;
    return 0.0;
  };
  const double mfs = r.listMs > 0 ? double(r.fragments) / r.listMs / 1000.0 : 0.0;
  const double ratio = r.floorMs > 0 ? r.listMs / r.floorMs : 0.0;
  if (o.json) {
    nlohmann::json passes = nlohmann::json::object();
    for (const auto& p : r.passes) passes[p.first] = p.second;
    j.push_back({{"sweep", r.sweep}, {"fill", r.fill}, {"scene", r.scene}, {"size", r.size}, {"triangles", r.triangles},
                 {"fragments", r.fragments}, {"pass_ms", passes}, {"total_ms", r.listMs},
                 {"fragments_per_second", mfs * 1e6}, {"unsorted_ms", r.floorMs}, {"ratio_to_unsorted", ratio}});
  } else {
    std::printf("%-10s %-8s %-36s %5d %9zu %9llu", r.sweep.c_str(), r.fill.c_str(), r.scene.c_str(), r.size, r.triangles,
                static_cast<unsigned long long>(r.fragments));
    for (const auto& n : passNames) std::printf(" %8.1f", get(n));
    std::printf(" %8.1f %9.1f %9.1f %7.1f\n", r.listMs, mfs, r.floorMs, ratio);
  }
}

// R² of total time against fragments over the resolution sweep of one fill method.
void reportFit(const BenchRenderOptions& o, const std::vector<bench::RenderSweepRow>& rows, render::FillMethod fill,
               nlohmann::json& j) {
  std::vector<double> x, y;
  for (const auto& r : rows)
    if (r.sweep == "resolution" && r.fill == render::fillMethodName(fill)) {
      x.push_back(double(r.fragments));
      y.push_back(r.listMs);
    }
  const double r2 = rSquared(x, y);
  if (o.json) j.push_back({{"fit", "total_ms ~ fragments (resolution sweep)"}, {"fill", render::fillMethodName(fill)}, {"r_squared", r2}});
  else std::printf("R^2 of a linear fit of total time vs. fragments over the resolution sweep (%s): %.4f\n",
                   render::fillMethodName(fill).c_str(), r2);
}

void runBenchRender(const BenchRenderOptions& o) {
  const auto context = gpu::createHeadlessContext();
  const std::vector<render::FillMethod> fills = benchFills(o);
  const std::vector<bench::RenderSweepRow> rows = runSweeps(o, fills);
  const std::vector<std::string> passNames = passColumns(rows);
  nlohmann::json j = nlohmann::json::array();
  if (!o.json) printTableHeader(o, passNames);
  for (const auto& r : rows) reportRow(o, r, passNames, j);
  for (const auto& fill : fills) reportFit(o, rows, fill, j);
  if (o.json) std::cout << j.dump(2) << "\n";
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  auto* bench = app.add_subcommand("bench", "Speed measurements (see also the Google Benchmark programs in bench/)");
  bench->require_subcommand(1);
  auto o = std::make_shared<BenchRenderOptions>();
  auto* render = bench->add_subcommand("render", "Per-pass timing of the illustration buffer vs. fragments and triangles (Carnecky Figs. 14-15)");
  render->add_flag("--json", o->json, "print JSON");
  render->add_flag("--quick", o->quick, "a smaller sweep (up to 512x512 and 100K triangles)");
  render->add_option("--fill", o->fill, "scatter, list or both")->capture_default_str();
  render->add_option("--style", o->style, "style to time")->capture_default_str();
  render->add_option("--repeats", o->repeats, "timed frames per configuration (median)")->capture_default_str()->check(CLI::Range(1, 100));
  auto scene = std::make_shared<SceneBenchOptions>();
  render->add_option("--scene", scene->scene,
                     "time one scene instead of the sweep: a glTF file or builtin:NAME (with --camera, --size, --frames; "
                     "--style may then list several styles, comma-separated: the first is the ratio's reference)");
  render->add_option("--camera", scene->camera, "with --scene: \"eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG\"");
  render->add_option("--size", scene->size, "with --scene: image size WxH")->capture_default_str();
  render->add_option("--frames", scene->frames, "with --scene: timed frames (median)")->capture_default_str()->check(CLI::Range(1, 1000));
  render->add_option("--set", scene->settings, "with --scene: style parameter key=value (repeatable)");
  render->add_option("--until", scene->until,
                     "with --scene: end every frame after this pass (fill, sort or a style's pass; the picture is left "
                     "unfinished), to count each pass's work (bench/count_instructions.sh)");
  render->add_flag("--parts", scene->parts,
                   "with --scene: also time each pass's parts (the connect pass's phases, the solve's steps, the fill's "
                   "rasterization and prefix sum, the compose's read-back), each between two glFinish calls");
  render->callback([o, scene, render] {
    if (scene->scene.empty()) {
      for (const char* only : {"--camera", "--size", "--frames", "--set", "--until", "--parts"})
        if (render->count(only) > 0) throw std::invalid_argument(std::string(only) + " needs --scene");
      return runBenchRender(*o);
    }
    scene->styles = splitList(o->style);
    scene->json = o->json;
    runSceneBench(*scene);
  });
  addBenchAll(*bench);
  addDiffusionBench(*bench);
  addPeelBench(*bench);
  addDynamicBench(*bench);
  addBucketBench(*bench);
  addFloorBench(*bench);
  addIntegrateBench(*bench);
}

}  // namespace tlab::app
