// tlab bench render --scene and tlab bench all (app/bench_scene.hpp).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/bench_scene.hpp"
#include "app/build_revision.hpp"
#include "bench/measure/frame_timing.hpp"
#include "app/gl_option.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gl_backend.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"
#include "renderer/styles/style_file.hpp"

namespace tlab::app {

namespace {

struct BenchRow {
  std::string scene, style, size, error;
  bench::FrameTiming timing;
  double ratio = 0;  // frame time over the reference style's on the same scene and size
};

nlohmann::json rowJson(const BenchRow& r) {
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& [name, ms] : r.timing.passes) passes[name] = ms;
  nlohmann::json j = {{"scene", r.scene}, {"style", r.style}, {"size", r.size}};
  if (!r.error.empty()) {
    j["error"] = r.error;
    return j;
  }
  if (render::isStyleFilePath(r.style))  // a style file: its identity, as in --stats-json
    if (const auto sha = render::findStyle(r.style).fileSha256()) j["style_sha256"] = *sha;
  j.update({{"fragments", r.timing.fragments}, {"frame_ms", r.timing.frameMs},
            {"fps", r.timing.frameMs > 0 ? 1000.0 / r.timing.frameMs : 0.0}, {"pass_ms", passes},
            {"ratio_to_reference", r.ratio}, {"operations", r.timing.operations}});
  if (!r.timing.parts.empty()) {
    nlohmann::json ms = nlohmann::json::object(), counts = nlohmann::json::object();
    for (const auto& part : r.timing.parts) {
      ms[part.name] = part.ms;
      counts[part.name] = part.count;
    }
    j.update({{"part_ms", ms}, {"part_counts", counts}});
  }
  return j;
}

void printRow(const BenchRow& r) {
  if (!r.error.empty()) {
    std::printf("%-38s %-9s %-16s failed: %s\n", r.scene.c_str(), r.size.c_str(), r.style.c_str(), r.error.c_str());
    return;
  }
  std::string passes;
  for (const auto& [name, ms] : r.timing.passes) {
    char b[64];
    std::snprintf(b, sizeof b, "%s%s %.1f", passes.empty() ? "" : ", ", name.c_str(), ms);
    passes += b;
  }
  std::printf("%-38s %-9s %-16s %10llu %10.1f %8.1f %7.2f  %s\n", r.scene.c_str(), r.size.c_str(), r.style.c_str(),
              static_cast<unsigned long long>(r.timing.fragments), r.timing.frameMs,
              r.timing.frameMs > 0 ? 1000.0 / r.timing.frameMs : 0.0, r.ratio, passes.c_str());
  if (r.timing.parts.empty()) return;
  std::string parts;  // "name ms (times run)"
  for (const auto& part : r.timing.parts) {
    char b[128];
    std::snprintf(b, sizeof b, "%s%s %.2f ms (%dx)", parts.empty() ? "" : ", ", part.name.c_str(), part.ms, part.count);
    parts += b;
  }
  std::printf("  parts: %s\n", parts.c_str());
}

void printHeader(const gpu::GpuInfo& gl, int frames, const std::string& reference) {
  std::printf("GL: %s | %s | %s | %s\n", gl.backend.c_str(), gl.vendor.c_str(), gl.renderer.c_str(), gl.version.c_str());
  std::printf("median of %d frames after a warm-up; ratio = frame ms / %s's on the same scene and size\n", frames,
              reference.c_str());
  std::printf("%-38s %-9s %-16s %10s %10s %8s %7s  %s\n", "scene", "size", "style", "fragments", "frame_ms", "fps", "ratio",
              "ms per pass");
}

// Every style of `styles` on one scene at one size, the first style being the ratio's reference.
std::vector<BenchRow> benchScene(const std::string& source, const std::string& camera, const std::vector<std::string>& styles,
                                 const std::vector<std::string>& settings, const std::string& size, int frames,
                                 const std::string& until = "", bool parts = false) {
  SceneOptions so;
  so.scene = source;
  so.camera = camera;
  so.size = size;
  so.settings = settings;
  render::Renderer renderer(render::loadScene(source, sceneCatalog()));
  std::vector<BenchRow> rows;
  for (const auto& style : styles) {
    BenchRow row;
    row.scene = source, row.style = style, row.size = size;
    try {
      so.style = style;
      render::RenderRequest request = so.request(renderer.scene());
      request.lastPass = until;
      request.timeParts = parts;
      row.timing = bench::timeFrames(renderer, request, frames);
    } catch (const std::exception& e) {
      row.error = e.what();
    }
    if (row.error.empty() && !rows.empty() && rows.front().error.empty() && rows.front().timing.frameMs > 0)
      row.ratio = row.timing.frameMs / rows.front().timing.frameMs;
    else if (rows.empty()) row.ratio = 1.0;
    rows.push_back(row);
  }
  return rows;
}

void report(const std::vector<BenchRow>& rows, const gpu::GpuInfo& gl, int frames, const std::string& reference, bool json) {
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : rows) list.push_back(rowJson(r));
    std::cout << nlohmann::json{{"gl", gpuInfoToJson(gl)}, {"tlab_version", versionString()}, {"frames", frames},
                                {"reference_style", reference}, {"rows", list}}
                     .dump(2)
              << "\n";
    return;
  }
  printHeader(gl, frames, reference);
  for (const auto& r : rows) printRow(r);
}

struct BenchAllOptions {
  std::vector<std::string> comparisons = {"buckets", "dynamic", "peel"};
  std::vector<std::string> sizes = {"512x512", "1024x1024"};
  std::vector<std::string> scenes = {"builtin:torus?triangles=100000", "builtin:quad-stack?n=16", "builtin:nested-spheres?n=3"};
  int frames = 5;
  bool json = false;
};

// The seeds' own comparisons (`tlab bench buckets|dynamic|peel`: Murray Fig. 10, Elmqvist Table
// 2, IRIS Sec. 5.1) with their papers' settings, each run by this executable with the same --gl.
// With `json` their JSON documents are returned, keyed by name; otherwise their tables are printed.
nlohmann::json runComparisons(const std::vector<std::string>& names, bool json) {
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
  nlohmann::json all = nlohmann::json::object();
  for (const auto& name : names) {
    const std::string command =
        "'" + exe + "' bench " + name + " --gl " + gpu::glChoiceName(gpu::glChoice()) + (json ? " --json" : "");
    std::fflush(stdout);
    std::string out;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) throw std::runtime_error("bench all: cannot run tlab bench " + name);
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
    const int status = ::pclose(pipe);
    if (status != 0) throw std::runtime_error("bench all: tlab bench " + name + " failed (see its message above)");
    if (json) all[name] = nlohmann::json::parse(out);
    else std::printf("\n%s", out.c_str());
  }
  return all;
}

void runBenchAll(const BenchAllOptions& o) {
  std::vector<BenchRow> rows;
  gpu::GpuInfo gl;
  {
    const auto context = gpu::createHeadlessContext();
    gl = context->info();
    std::vector<std::string> styles = {"constant"};  // the reference first
    for (const auto& s : render::styleNames())
      if (s != "constant") styles.push_back(s);
    for (const auto& scene : o.scenes)
      for (const auto& size : o.sizes) {
        auto part = benchScene(scene, "", styles, {}, size, o.frames);
        rows.insert(rows.end(), part.begin(), part.end());
      }
  }  // the comparisons run in processes of their own
  if (!o.json) {
    report(rows, gl, o.frames, "constant", false);
    runComparisons(o.comparisons, false);
    return;
  }
  nlohmann::json list = nlohmann::json::array();
  for (const auto& r : rows) list.push_back(rowJson(r));
  std::cout << nlohmann::json{{"gl", gpuInfoToJson(gl)}, {"tlab_version", versionString()}, {"frames", o.frames},
                              {"reference_style", "constant"}, {"rows", list},
                              {"comparisons", runComparisons(o.comparisons, true)}}.dump(2)
            << "\n";
}

}  // namespace

void runSceneBench(const SceneBenchOptions& o) {
  if (o.styles.empty()) throw std::invalid_argument("--style: give at least one style");
  for (const auto& s : o.styles) render::findStyle(s);  // unknown style: fail before any GL work
  parseSize(o.size);
  const auto context = gpu::createHeadlessContext();
  const auto rows = benchScene(o.scene, o.camera, o.styles, o.settings, o.size, o.frames, o.until, o.parts);
  if (!o.until.empty())  // a frame cut short elsewhere than asked measures nothing: say so and stop
    for (const auto& r : rows)
      if (!r.error.empty()) throw std::invalid_argument("--until: " + r.error);
  report(rows, context->info(), o.frames, o.styles.front(), o.json);
}

void addBenchAll(CLI::App& bench) {
  auto o = std::make_shared<BenchAllOptions>();
  auto* cmd = bench.add_subcommand("all", "Every style at 512x512 and 1024x1024 on the standard scenes (the table to run on a lab's GPU)");
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->add_option("--frames", o->frames, "timed frames per row (median)")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--sizes", o->sizes, "image sizes WxH")->delimiter(',')->capture_default_str();
  cmd->add_option("--scenes", o->scenes, "scenes")->delimiter(',')->capture_default_str();
  cmd->add_option("--comparisons", o->comparisons,
                  "the seeds' comparisons to run after the table (tlab bench buckets, dynamic, peel), or none")
      ->delimiter(',')
      ->capture_default_str();
  cmd->callback([o] {
    if (o->comparisons == std::vector<std::string>{"none"}) o->comparisons.clear();
    for (const auto& name : o->comparisons)  // before any work
      if (name != "buckets" && name != "dynamic" && name != "peel")
        throw std::invalid_argument("--comparisons: '" + name + "' is not buckets, dynamic or peel (or none)");
    runBenchAll(*o);
  });
}

}  // namespace tlab::app
