#pragma once
// Options shared by the subcommands that render a scene: SCENE, --style, --set, --size,
// --camera, --fill, --pool. Parsing only; the work is in the renderer library.
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"

namespace tlab::app {

struct SceneOptions {
  std::string scene;
  std::string style = "constant";
  std::vector<std::string> settings;
  std::string size = "512x512";
  std::string camera;
  std::string fill = "scatter";
  std::size_t pool = 0;

  void addTo(CLI::App& cmd);
  render::RenderRequest request(const render::Scene& scene) const;
};

// "WxH" → (W, H); throws naming the option.
std::pair<int, int> parseSize(const std::string& text);

// The built-in scenes the command line knows.
const std::vector<render::BuiltinSceneSpec>& sceneCatalog();

}  // namespace tlab::app
