// tlab render: one picture of a scene in a transparency style.
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "app/stats_json.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/gpu/window_context.hpp"
#include "core/image.hpp"
#include "core/parse_number.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"
#include "renderer/styles/style_file.hpp"

namespace tlab::app {

namespace {

struct RenderOptions {
  SceneOptions scene;
  std::string output;
  std::string statsJson;
  std::string layersOut;
  std::string renderer = "buffer";
  bool window = false;
};

// The styles and their --set keys, for the help text.
std::string styleListing() {
  std::string out = "Styles (--style NAME) and their parameters (--set key=value):\n";
  for (const auto& name : render::styleNames()) {
    const auto& style = render::findStyle(name);
    out += "  " + name + ": " + style.description() + "\n";
    for (const auto& p : style.params()) out += "      " + p.name + "=" + p.defaultValue + "  " + p.help + "\n";
  }
  return out + "  (every style also takes lighting=headlight|none)";
}

// One style file's parameters (--set key=value) with their defaults and ranges.
std::string styleFileListing(const render::Style& style, const std::string& path) {
  std::string out = "Style file " + path + " (" + style.name() + "): " + style.description() + "\nParameters (--set key=value):\n";
  for (const auto& p : style.allParams()) {
    std::ostringstream range;
    if (p.kind == render::ParamSpec::Kind::Number) range << "  [" << core::roundTripText(p.minValue) << ", " << core::roundTripText(p.maxValue) << "]";
    else for (std::size_t i = 0; i < p.choices.size(); ++i) range << (i ? "|" : "  ") << p.choices[i];
    out += "  " + p.name + "=" + p.defaultValue + range.str() + "  " + p.help + "\n";
  }
  return out;
}

// `tlab render --style FILE --help`: the style file's own declarations, else the built-in listing.
std::string styleHelp(const CLI::App& cmd) {
  const auto& given = cmd.get_option("--style")->results();
  if (given.empty() || !render::isStyleFilePath(given.back())) return styleListing();
  try {
    return styleFileListing(render::findStyle(given.back()), given.back());
  } catch (const std::exception& e) {
    return std::string("Style file: ") + e.what();
  }
}

void runRender(const RenderOptions& o) {
  if (o.output.empty() && !o.window) throw std::invalid_argument("render: give -o FILE.png (or --window)");
  render::Scene scene = render::loadScene(o.scene.scene, sceneCatalog());
  render::RenderRequest request = o.scene.request(scene);
  std::unique_ptr<gpu::GpuContext> context;
  gpu::WindowContext* window = nullptr;
  if (o.window) {
    auto w = gpu::createWindowContext(request.width, request.height, "tlab render - " + o.scene.scene);
    window = w.get();
    context = std::move(w);
  } else {
    context = gpu::createHeadlessContext();
  }
  if (o.renderer != "buffer" && o.renderer != "peel") throw std::invalid_argument("--renderer must be buffer or peel");
  if (o.renderer == "peel" && !o.layersOut.empty()) throw std::invalid_argument("--layers-out needs --renderer buffer");
  request.depthPeeling = o.renderer == "peel";  // IRIS Sec. 5.1, local styles only
  render::RenderStats stats;
  render::Renderer renderer(std::move(scene));
  const core::Image image = renderer.render(request, &stats);
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> files;  // written all or none
  if (!o.output.empty()) files.emplace_back(o.output, core::encodePng(image));
  if (!o.layersOut.empty())
    files.emplace_back(o.layersOut, core::encodePgm16(renderer.layerCounts(), image.width, image.height));
  if (!o.statsJson.empty()) {
    nlohmann::json j = statsToJson(stats, context->info());
    j["style"] = request.style;
    if (const auto sha = render::findStyle(request.style).fileSha256()) j["style_sha256"] = *sha;
    j["settings"] = request.settings;
    j["scene"] = o.scene.scene;
    j["renderer"] = o.renderer;
    if (request.depthPeeling) j["peel_iterations"] = stats.peelIterations;
    const std::string text = j.dump(2) + "\n";
    files.emplace_back(o.statsJson, std::vector<std::uint8_t>(text.begin(), text.end()));
  }
  core::writeFilesAtomically(files);
  if (!o.output.empty()) std::cout << "wrote " << o.output << " (" << image.width << "x" << image.height << ")\n";
  if (window) {
    const auto rgba = core::toRgba8(image);
    window->showUntilClosed(rgba.data(), image.width, image.height);
  }
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand("render", "Render a scene in a transparency style to a PNG");
  options->scene.addTo(*cmd);
  cmd->add_option("-o,--output", options->output, "output PNG (row 0 = top of the picture)");
  cmd->add_option("--stats-json", options->statsJson,
                  "write fragment counts, list lengths, per-pass ms, re-renders and the camera used");
  cmd->add_option("--layers-out", options->layersOut, "write the per-pixel fragment count as a 16-bit PGM");
  cmd->add_option("--renderer", options->renderer,
                  "buffer (the illustration buffer) or peel (depth peeling, local styles only: IRIS Sec. 5.1)")
      ->capture_default_str();
  cmd->add_flag("--window", options->window, "show the result in a GLFW window instead of rendering headless");
  cmd->footer([cmd] { return styleHelp(*cmd); });
  cmd->callback([options] { runRender(*options); });
}

}  // namespace tlab::app
