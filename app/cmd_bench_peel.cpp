// tlab bench peel: the illustration buffer against depth peeling (IRIS Sec. 5.1) on the same
// frames, for L = 2, 4, 8, 16, 32 layers of full-screen grids with at least 100K triangles, and
// the time ratio per L. Depth peeling rasterizes the scene L + 1 times; the buffer once (twice
// for the count and scatter halves of its fill), so the ratio should grow about linearly in L.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "bench/measure/gl_timing.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gl.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/peel/layered_grid_scene.hpp"
#include "renderer/pipeline/renderer.hpp"

namespace tlab::app {

namespace {

struct PeelBenchOptions {
  std::string size = "512x512";
  std::string style = "constant";
  std::vector<std::string> settings;
  std::size_t triangles = 100000;
  std::vector<int> layers = {2, 4, 8, 16, 32};
  int repeats = 3;
  bool json = false;
};

void runPeelBench(const PeelBenchOptions& o) {
  const auto context = gpu::createHeadlessContext();
  render::RenderRequest request;
  std::tie(request.width, request.height) = parseSize(o.size);
  request.style = o.style;
  for (const auto& s : o.settings) render::addSetting(request.settings, s);
  request.timePasses = false;
  nlohmann::json rows = nlohmann::json::array();
  if (!o.json)
    std::printf("tlab bench peel: style %s, %dx%d, median of %d frames; target buffer >= L/2 x faster for L >= 8\n",
                o.style.c_str(), request.width, request.height, o.repeats);
  if (!o.json)
    std::printf("%4s %9s %10s %10s %10s %10s %8s %8s\n", "L", "triangles", "fragments", "buffer_ms", "peel_ms", "iterations",
                "ratio", "L/2");
  for (int L : o.layers) {
    const render::Scene scene = render::makeLayeredGridScene(L, o.triangles);
    render::Renderer buffer(scene);
    render::Renderer peeler(scene);
    render::RenderRequest peelRequest = request;
    peelRequest.depthPeeling = true;
    render::RenderStats bufferStats;
    render::RenderStats peelStats;
    const double bufferMs = bench::medianFrameMs(o.repeats, [&] { buffer.render(request, &bufferStats); });
    const double peelMs = bench::medianFrameMs(o.repeats, [&] { peeler.render(peelRequest, &peelStats); });
    const double ratio = peelMs / bufferMs;
    if (o.json) {
      rows.push_back({{"layers", L}, {"triangles", scene.triangleCount()}, {"fragments", bufferStats.fragments},
                      {"buffer_ms", bufferMs}, {"peel_ms", peelMs}, {"peel_iterations", peelStats.peelIterations},
                      {"ratio", ratio}, {"target", L / 2.0}});
    } else {
      std::printf("%4d %9zu %10llu %10.1f %10.1f %10d %8.2f %8.1f\n", L, scene.triangleCount(),
                  static_cast<unsigned long long>(bufferStats.fragments), bufferMs, peelMs, peelStats.peelIterations, ratio, L / 2.0);
    }
  }
  if (o.json) std::cout << rows.dump(2) << "\n";
}

}  // namespace

void addPeelBench(CLI::App& bench) {
  auto o = std::make_shared<PeelBenchOptions>();
  auto* cmd = bench.add_subcommand("peel", "The illustration buffer against depth peeling (IRIS Sec. 5.1) for L = 2..32 layers");
  cmd->add_option("--size", o->size, "image size WxH")->capture_default_str();
  cmd->add_option("--style", o->style, "a local style (constant, angle, normal-variation, iris)")->capture_default_str();
  cmd->add_option("--set", o->settings, "style parameter key=value (repeatable)");
  cmd->add_option("--triangles", o->triangles, "minimum triangles per scene")->capture_default_str();
  cmd->add_option("--layers", o->layers, "layer counts L")->capture_default_str();
  cmd->add_option("--repeats", o->repeats, "timed frames per configuration (median)")->capture_default_str()->check(CLI::Range(1, 100));
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->callback([o] { runPeelBench(*o); });
}

}  // namespace tlab::app
