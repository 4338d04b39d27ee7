// tlab bench floor: each pass's bytes read and written per frame (bench/measure/traffic_floor),
// this machine's streaming bandwidth, the floor time those bytes take at that bandwidth, and the
// measured time over the floor — so "near the memory limit" is a printed number (issue #29).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/bench_floor.hpp"
#include "app/scene_options.hpp"
#include "bench/measure/frame_timing.hpp"
#include "bench/measure/traffic_floor.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"

namespace tlab::app {

namespace {

struct FloorBenchOptions {
  std::vector<std::string> scenes = {"builtin:torus?triangles=100000", "builtin:quad-stack?n=16"};
  std::vector<std::string> styles = {"constant", "smart"};
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
};

// The modelled passes of one style on one scene, with their median times.
std::vector<FloorRow> measureScene(render::Renderer& renderer, const FloorBenchOptions& o, const std::string& scene,
                                   const std::string& style) {
  SceneOptions so;
  so.scene = scene, so.style = style, so.camera = o.camera, so.size = o.size;
  const render::RenderRequest request = so.request(renderer.scene());
  const bench::FrameTiming timing = bench::timeFrames(renderer, request, o.frames);
  render::RenderStats stats;
  renderer.render(request, &stats);
  const auto shape = bench::frameShape(stats, style, render::findStyle(style).resolve(request.settings));
  std::vector<std::string> names;
  for (const auto& p : timing.passes) names.push_back(p.first);
  std::vector<FloorRow> rows;
  for (const auto& t : bench::passTraffic(shape, names)) {
    FloorRow r{scene, style, stats.fragments, t.pass, 0.0, t};
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
  {
    const auto context = gpu::createHeadlessContext();
    for (const auto& scene : o.scenes) {
      render::Renderer renderer(render::loadScene(scene, sceneCatalog()));
      for (const auto& style : o.styles) {
        auto part = measureScene(renderer, o, scene, style);
        rows.insert(rows.end(), part.begin(), part.end());
      }
    }
  }
  const auto floorMs = [&](const FloorRow& r) { return 1000.0 * (r.traffic.bytesRead + r.traffic.bytesWritten) / bandwidth; };
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : rows)
      list.push_back({{"scene", r.scene}, {"style", r.style}, {"fragments", r.fragments}, {"pass", r.pass}, {"ms", r.ms},
                      {"bytes_read", r.traffic.bytesRead}, {"bytes_written", r.traffic.bytesWritten}, {"floor_ms", floorMs(r)},
                      {"ratio", r.ms / floorMs(r)}, {"model", r.traffic.model}});
    std::cout << nlohmann::json{{"copy_bandwidth_1_thread", one}, {"copy_bandwidth_all_threads", two}, {"size", o.size},
                                {"frames", o.frames}, {"rows", list}}.dump(2)
              << "\n";
    return;
  }
  std::printf("streaming copy of %zu MiB (read + write counted): %.2f GB/s on 1 thread, %.2f GB/s on %u; floor at %.2f GB/s\n",
              o.copyMiB, one / 1e9, two / 1e9, std::max(2u, std::thread::hardware_concurrency()), bandwidth / 1e9);
  std::printf("%s, median of %d frames per pass; floor = (read + written) / bandwidth\n", o.size.c_str(), o.frames);
  std::printf("%-32s %-9s %10s %-8s %9s %9s %9s %9s %7s\n", "scene", "style", "fragments", "pass", "ms", "read_MB",
              "write_MB", "floor_ms", "ratio");
  for (const auto& r : rows)
    std::printf("%-32s %-9s %10llu %-8s %9.2f %9.2f %9.2f %9.3f %7.1f\n", r.scene.c_str(), r.style.c_str(),
                static_cast<unsigned long long>(r.fragments), r.pass.c_str(), r.ms, r.traffic.bytesRead / 1e6,
                r.traffic.bytesWritten / 1e6, floorMs(r), r.ms / floorMs(r));
  std::printf("models:\n");
  std::vector<std::string> lines;  // each once
  for (const auto& r : rows) {
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
  cmd->add_option("--camera", o->camera, "\"eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG\" for every scene");
  cmd->add_option("--size", o->size, "image size WxH")->capture_default_str();
  cmd->add_option("--frames", o->frames, "timed frames (median)")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--copy-mib", o->copyMiB, "size of the streaming copy that measures the bandwidth")
      ->capture_default_str()
      ->check(CLI::Range(16, 4096));
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->callback([o] {
    for (const auto& s : o->styles) render::findStyle(s);  // unknown style: fail before any work
    parseSize(o->size);
    runFloorBench(*o);
  });
}

}  // namespace tlab::app
