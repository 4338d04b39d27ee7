// tlab bench dynamic: the frame time of dynamic transparency (Elmqvist et al., seed 004,
// Table 2: ABSTRACT, 13K polygons, 800x600, 87 fps standard vs. 33 fps dynamic on a GeForce 7800)
// against the `opaque` style on the same scene and the same frames. The camera orbits the scene
// by a few degrees per frame, as a user orbiting would, so the frame-coherent group re-sorting is
// part of the measurement.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "bench/measure/frame_timing.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gl.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"

namespace tlab::app {

namespace {

struct DynamicBenchOptions {
  std::string scene = "builtin:abstract";
  std::string size = "800x600";
  std::vector<std::string> settings;
  int frames = 10;
  double degreesPerFrame = 2.0;
  bool json = false;
};

void runDynamicBench(const DynamicBenchOptions& o) {
  const auto context = gpu::createHeadlessContext();
  render::Renderer renderer(render::loadScene(o.scene, sceneCatalog()));
  render::RenderRequest request;
  std::tie(request.width, request.height) = parseSize(o.size);
  for (const auto& s : o.settings) render::addSetting(request.settings, s);
  const render::Camera start = renderer.resolveCamera(request);
  std::vector<render::Camera> orbit;
  for (int i = 0; i < o.frames; ++i) {
    render::Camera c = start;
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(float(o.degreesPerFrame * i)), start.up);
    c.eye = start.target + glm::vec3(turn * glm::vec4(start.eye - start.target, 0.0f));
    orbit.push_back(c);
  }
  render::RenderRequest opaque = request;
  opaque.style = "opaque";
  opaque.settings.clear();
  render::RenderRequest dynamic = request;
  dynamic.style = "dynamic";
  render::findStyle("dynamic").resolve(dynamic.settings);  // bad --set: fail before timing
  const bench::OrbitTiming opaqueTime = bench::timeOrbit(renderer, opaque, orbit);
  const bench::OrbitTiming dynamicTime = bench::timeOrbit(renderer, dynamic, orbit);
  const double ratio = dynamicTime.medianMs / opaqueTime.medianMs;
  if (o.json) {
    nlohmann::json passes = nlohmann::json::object();
    for (const auto& [name, ms] : dynamicTime.passes) passes[name] = ms;
    std::cout << nlohmann::json{{"scene", o.scene}, {"size", o.size}, {"triangles", renderer.scene().triangleCount()},
                                {"objects", renderer.scene().objects.size()}, {"frames", o.frames},
                                {"opaque_ms", opaqueTime.medianMs}, {"dynamic_ms", dynamicTime.medianMs},
                                {"opaque_fps", 1000.0 / opaqueTime.medianMs}, {"dynamic_fps", 1000.0 / dynamicTime.medianMs},
                                {"ratio", ratio}, {"fragments", dynamicTime.fragments}, {"dynamic_pass_ms", passes}}
                     .dump(2)
              << "\n";
    return;
  }
  std::printf("tlab bench dynamic: %s, %s, %zu objects, %zu triangles, %llu fragments; median of %d orbiting frames (%.1f deg/frame)\n",
              o.scene.c_str(), o.size.c_str(), renderer.scene().objects.size(), renderer.scene().triangleCount(),
              static_cast<unsigned long long>(dynamicTime.fragments), o.frames, o.degreesPerFrame);
  std::printf("%-8s %10s %8s\n", "style", "frame_ms", "fps");
  std::printf("%-8s %10.1f %8.1f\n", "opaque", opaqueTime.medianMs, 1000.0 / opaqueTime.medianMs);
  std::printf("%-8s %10.1f %8.1f\n", "dynamic", dynamicTime.medianMs, 1000.0 / dynamicTime.medianMs);
  std::printf("dynamic / opaque: %.2f (paper, GeForce 7800, ABSTRACT 800x600: 87 vs. 33 fps, 2.6)\n", ratio);
  std::printf("dynamic passes (last frame, ms):");
  for (const auto& [name, ms] : dynamicTime.passes) std::printf(" %s %.1f", name.c_str(), ms);
  std::printf("\n");
}

}  // namespace

void addDynamicBench(CLI::App& bench) {
  auto o = std::make_shared<DynamicBenchOptions>();
  auto* cmd = bench.add_subcommand("dynamic", "Dynamic transparency (Elmqvist Table 2) against the opaque style on the same frames");
  cmd->add_option("scene", o->scene, "scene (default: the ABSTRACT world)")->capture_default_str();
  cmd->add_option("--size", o->size, "image size WxH")->capture_default_str();
  cmd->add_option("--set", o->settings, "dynamic style parameter key=value (repeatable)");
  cmd->add_option("--frames", o->frames, "timed frames (median)")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--orbit", o->degreesPerFrame, "camera orbit per frame in degrees")->capture_default_str();
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->callback([o] { runDynamicBench(*o); });
}

}  // namespace tlab::app
