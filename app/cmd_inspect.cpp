// tlab inspect: one pixel's sorted fragment list, front to back.
#include <cstdio>
#include <iostream>
#include <regex>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/scene/scene_source.hpp"

namespace tlab::app {

namespace {

struct InspectOptions {
  SceneOptions scene;
  std::string pixel;
  bool json = false;
};

void runInspect(const InspectOptions& o) {
  static const std::regex pattern(R"(^(\d+),(\d+)$)");
  std::smatch m;
  if (!std::regex_match(o.pixel, m, pattern)) throw std::invalid_argument("--pixel: expected X,Y, got '" + o.pixel + "'");
  const int x = std::stoi(m[1]), y = std::stoi(m[2]);
  render::Scene scene = render::loadScene(o.scene.scene, sceneCatalog());
  render::RenderRequest request = o.scene.request(scene);
  request.allProperties = true;
  if (request.style == "opaque") request.style = "constant";  // lists are what we inspect
  const auto context = gpu::createHeadlessContext();
  render::Renderer renderer(std::move(scene));
  renderer.render(request);
  const auto list = renderer.fragmentsAt(x, y);
  if (o.json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& f : list)
      j.push_back({{"depth", f.depth}, {"triangle", f.triangle}, {"object", f.object}, {"component", f.component},
                   {"front_facing", f.frontFacing}, {"normal", {f.normal.x, f.normal.y, f.normal.z}},
                   {"depth_gradient", {f.depthGradient.x, f.depthGradient.y}}, {"st", {f.st.x, f.st.y}},
                   {"color", {f.color.r, f.color.g, f.color.b}}});
    std::cout << nlohmann::json{{"pixel", {x, y}}, {"fragments", j}}.dump(2) << "\n";
    return;
  }
  std::printf("pixel (%d, %d): %zu fragment%s, front to back\n", x, y, list.size(), list.size() == 1 ? "" : "s");
  std::printf("%5s %12s %9s %6s %5s %5s %26s %9s\n", "layer", "depth", "triangle", "object", "comp", "face", "normal (view)", "s,t");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto& f = list[i];
    std::printf("%5zu %12.6f %9u %6u %5u %5s %8.4f,%8.4f,%8.4f %4.2f,%4.2f\n", i + 1, f.depth, f.triangle, f.object,
                f.component, f.frontFacing ? "front" : "back", f.normal.x, f.normal.y, f.normal.z, f.st.x, f.st.y);
  }
}

}  // namespace

void addInspectCommand(CLI::App& app) {
  auto options = std::make_shared<InspectOptions>();
  auto* cmd = app.add_subcommand("inspect", "Print one pixel's sorted fragment list");
  options->scene.addTo(*cmd);
  cmd->add_option("--pixel", options->pixel, "X,Y with row 0 = top")->required();
  cmd->add_flag("--json", options->json, "print JSON");
  cmd->callback([options] { runInspect(*options); });
}

}  // namespace tlab::app
