// tlab bench floor: each pass's bytes read and written per frame (bench/measure/traffic_floor),
// this machine's streaming bandwidth, the floor time those bytes take at that bandwidth, and the
// measured time over the floor — so "near the memory limit" is a printed number (issue #29). Beside
// it, gl_ratio: the time over those bytes at the rate the fastest copying compute shader reaches on
// this GL (bench/measure/gl_stream_copy), what a pass could reach that only streamed its bytes.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/bench_floor.hpp"
#include "app/scene_options.hpp"
#include "bench/measure/frame_timing.hpp"
#include "bench/measure/gl_stream_copy.hpp"
#include "bench/measure/traffic_floor.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"

namespace tlab::app {

namespace {

struct FloorBenchOptions {
  std::vector<std::string> scenes = {"builtin:torus?triangles=100000", "builtin:quad-stack?n=16"};
  std::vector<std::string> styles = {"constant", "smart"};
  std::vector<std::string> settings;  // key=value for every style
  std::string camera;
  std::string size = "512x512";
  int frames = 5;
  std::size_t copyMiB = 256;
  bool json = false;
};

struct FloorRow {
  std::string scene, style;
  std::uint64_t fragments = 0;
  std::string pass;
  double ms = 0;  // median measured
  bench::PassTraffic traffic;
  bench::SolveShape solve;  // what smart's solve worked on (the solve row reports it)
  std::string error;        // why this style could not run on this scene (the other rows still count)
};

nlohmann::json solveJson(const bench::SolveShape& v) {
  return {{"alpha_sweeps", v.alphaSweeps}, {"beta_sweeps", v.betaSweeps}, {"gamma_sweeps", v.gammaSweeps},
          {"beta_seeds", v.betaSeeds}, {"beta_reached", v.betaReached}, {"gamma_seeds", v.gammaSeeds},
          {"gamma_reached", v.gammaReached}};
}

// The modelled passes of one style on one scene, with their median times.
std::vector<FloorRow> measureScene(render::Renderer& renderer, const FloorBenchOptions& o, const std::string& scene,
                                   const std::string& style) {
  SceneOptions so;
  so.scene = scene, so.style = style, so.camera = o.camera, so.size = o.size, so.settings = o.settings;
  const render::RenderRequest request = so.request(renderer.scene());
  const bench::FrameTiming timing = bench::timeFrames(renderer, request, o.frames);
  render::RenderStats stats;
  renderer.render(request, &stats);
  const auto shape = bench::frameShape(stats, style, render::findStyle(style).resolve(request.settings), &renderer.transparencyFields());
  std::vector<std::string> names;
  for (const auto& p : timing.passes) names.push_back(p.first);
  std::vector<FloorRow> rows;
  for (const auto& t : bench::passTraffic(shape, names)) {
    FloorRow r{scene, style, stats.fragments, t.pass, 0.0, t, shape.solve, {}};
    for (const auto& p : timing.passes)
      if (p.first == t.pass) r.ms = p.second;
    rows.push_back(r);
  }
  return rows;
}

void runFloorBench(const FloorBenchOptions& o) {
  const std::size_t bytes = o.copyMiB << 20;
  const double one = bench::streamingBandwidth(bytes, 1, 5);
  const double two = bench::streamingBandwidth(bytes, std::max(2u, std::thread::hardware_concurrency()), 5);
  const double bandwidth = std::max(one, two);  // bytes/s, read + write
  std::vector<FloorRow> rows;
  std::vector<bench::GlCopyRate> glRates;  // compute shaders' streaming copies on this GL
  {
    const auto context = gpu::createHeadlessContext();
    glRates = bench::glStreamingRates(bytes, 5);
    for (const auto& scene : o.scenes) {
      render::Renderer renderer(render::loadScene(scene, sceneCatalog()));
      for (const auto& style : o.styles) {
        try {
          auto part = measureScene(renderer, o, scene, style);
          rows.insert(rows.end(), part.begin(), part.end());
        } catch (const std::exception& e) {  // e.g. more fragments than this GL's buffers hold
          FloorRow failed;
          failed.scene = scene, failed.style = style, failed.error = e.what();
          rows.push_back(failed);
        }
      }
    }
  }
  const bench::GlCopyRate glBest = bench::fastest(glRates);
  const double glBandwidth = glBest.bytesPerSecond;
  const auto floorMs = [&](const FloorRow& r) { return 1000.0 * (r.traffic.bytesRead + r.traffic.bytesWritten) / bandwidth; };
  // The same bytes at the rate a copying compute shader reaches on this GL.
  const auto glRatio = [&](const FloorRow& r) { return r.ms / floorMs(r) * glBandwidth / bandwidth; };
  const auto moves = [](const FloorRow& r) { return r.traffic.bytesRead + r.traffic.bytesWritten > 0; };
  // A pass with nothing to move (a solve with no seeds) has no ratio.
  const auto ratioJson = [&](double v, const FloorRow& r) { return moves(r) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  const auto ratioText = [&](double v, const FloorRow& r, int width) {
    char b[32];
    std::snprintf(b, sizeof b, "%*.1f", width, v);
    return moves(r) ? std::string(b) : std::string(std::size_t(width - 1), ' ') + "-";
  };
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : rows)
      if (!r.error.empty())
        list.push_back({{"scene", r.scene}, {"style", r.style}, {"error", r.error}});
      else
        list.push_back({{"scene", r.scene}, {"style", r.style}, {"fragments", r.fragments}, {"pass", r.pass}, {"ms", r.ms},
                      {"bytes_read", r.traffic.bytesRead}, {"bytes_written", r.traffic.bytesWritten}, {"floor_ms", floorMs(r)},
                      {"solve", r.pass == "solve" ? solveJson(r.solve) : nlohmann::json(nullptr)},
                      {"ratio", ratioJson(r.ms / floorMs(r), r)}, {"gl_ratio", ratioJson(glRatio(r), r)}, {"model", r.traffic.model}});
    std::cout << nlohmann::json{{"copy_bandwidth_1_thread", one}, {"copy_bandwidth_all_threads", two},
                                {"gl_copy_bandwidth", glBandwidth},
                                {"gl_copy_words_per_invocation", glBest.wordsPerInvocation}, {"size", o.size},
                                {"frames", o.frames}, {"rows", list}}.dump(2)
              << "\n";
    return;
  }
  std::printf("streaming copy of %zu MiB (read + write counted): %.2f GB/s on 1 thread, %.2f GB/s on %u; floor at %.2f GB/s\n",
              o.copyMiB, one / 1e9, two / 1e9, std::max(2u, std::thread::hardware_concurrency()), bandwidth / 1e9);
  std::printf("a compute shader's streaming copy on this GL:");
  for (const auto& r : glRates) std::printf(" %.2f GB/s with %d word(s) per invocation;", r.bytesPerSecond / 1e9, r.wordsPerInvocation);
  std::printf(" the best is %.1f times below the copy on the CPU\n", bandwidth / glBandwidth);
  std::printf("%s, median of %d frames per pass; floor = (read + written) / bandwidth; gl_ratio = ms over those bytes "
              "at the GL copy's rate\n", o.size.c_str(), o.frames);
  std::printf("%-32s %-9s %10s %-8s %9s %9s %9s %9s %7s %8s\n", "scene", "style", "fragments", "pass", "ms", "read_MB",
              "write_MB", "floor_ms", "ratio", "gl_ratio");
  for (const auto& r : rows)
    if (!r.error.empty())
      std::printf("%-32s %-9s failed: %s\n", r.scene.c_str(), r.style.c_str(), r.error.c_str());
    else
      std::printf("%-32s %-9s %10llu %-8s %9.2f %9.2f %9.2f %9.3f %s %s\n", r.scene.c_str(), r.style.c_str(),
                static_cast<unsigned long long>(r.fragments), r.pass.c_str(), r.ms, r.traffic.bytesRead / 1e6,
                r.traffic.bytesWritten / 1e6, floorMs(r), ratioText(r.ms / floorMs(r), r, 7).c_str(),
                ratioText(glRatio(r), r, 8).c_str());
  std::printf("models:\n");
  std::vector<std::string> lines;  // each once
  for (const auto& r : rows) {
    if (!r.error.empty()) continue;
    const std::string line = "  " + r.pass + " (" + r.style + "): " + r.traffic.model;
    if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
  }
  for (const auto& line : lines) std::printf("%s\n", line.c_str());
}

}  // namespace

void addFloorBench(CLI::App& bench) {
  auto o = std::make_shared<FloorBenchOptions>();
  auto* cmd = bench.add_subcommand("floor", "Each pass's bytes per frame against this machine's streaming bandwidth (the memory floor)");
  cmd->add_option("--scenes", o->scenes, "scenes (glTF files or builtin:NAME)")->delimiter(',')->capture_default_str();
  cmd->add_option("--styles", o->styles, "styles")->delimiter(',')->capture_default_str();
  cmd->add_option("--set", o->settings, "style parameter key=value for every style (repeatable)");
  cmd->add_option("--camera", o->camera, "\"eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG\" for every scene");
  cmd->add_option("--size", o->size, "image size WxH")->capture_default_str();
  cmd->add_option("--frames", o->frames, "timed frames (median)")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--copy-mib", o->copyMiB, "size of the streaming copy that measures the bandwidth")
      ->capture_default_str()
      ->check(CLI::Range(16, 4096));
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->callback([o] {
    for (const auto& s : o->styles) {  // unknown style or setting: fail before any work
      std::map<std::string, std::string> settings;
      for (const auto& kv : o->settings) render::addSetting(settings, kv);
      render::findStyle(s).resolve(settings);
    }
    parseSize(o->size);
    runFloorBench(*o);
  });
}

}  // namespace tlab::app
