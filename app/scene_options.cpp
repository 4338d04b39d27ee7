#include "app/scene_options.hpp"

#include <regex>
#include <stdexcept>

#include "renderer/styles/style.hpp"
#include "study/design/scene_catalog.hpp"

namespace tlab::app {

void SceneOptions::addTo(CLI::App& cmd) {
  cmd.add_option("scene", scene, "a glTF file (.gltf/.glb) or builtin:NAME[?param=value&...]")->required();
  cmd.add_option("--style", style, "transparency style")->capture_default_str();
  cmd.add_option("--set", settings, "style parameter key=value (repeatable)");
  cmd.add_option("--size", size, "image size WxH")->capture_default_str();
  cmd.add_option("--camera", camera, "\"eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG [near=N far=F]\"");
  cmd.add_option("--fill", fill, "how to fill the illustration buffer: scatter (count, prefix sum, scatter) or list (Carnecky Alg. 1)")
      ->capture_default_str();
  cmd.add_option("--pool", pool, "initial fragment pool size (0: one per pixel); it grows as needed");
}

std::pair<int, int> parseSize(const std::string& text) {
  static const std::regex pattern(R"(^(\d{1,5})x(\d{1,5})$)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) throw std::invalid_argument("--size: expected WxH, got '" + text + "'");
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throw std::invalid_argument("--size: " + text + " is outside 1x1 .. 16384x16384");
  return {w, h};
}

const std::vector<render::BuiltinSceneSpec>& sceneCatalog() { return study::sceneCatalog(); }

render::RenderRequest SceneOptions::request(const render::Scene& scene) const {
  render::RenderRequest r;
  std::tie(r.width, r.height) = parseSize(size);
  r.style = style;
  for (const auto& s : settings) render::addSetting(r.settings, s);
  render::findStyle(style).resolve(r.settings);  // unknown style or bad --set: fail before any GL work
  r.fill = render::parseFillMethod(fill);
  r.initialPoolFragments = pool;
  if (!camera.empty()) {
    const render::BoundingSphere sphere = scene.boundingSphere();
    render::Camera base = scene.camera ? *scene.camera : render::fitCamera(sphere, float(r.width) / float(r.height));
    render::Camera c = render::parseCamera(camera, base);
    const bool clipGiven = camera.find("near=") != std::string::npos || camera.find("far=") != std::string::npos;
    r.camera = clipGiven ? c : render::fitClipPlanes(c, sphere);
  }
  return r;
}

}  // namespace tlab::app
