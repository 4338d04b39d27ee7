#include "stimuli/sets/stimulus_set_names.hpp"

#include <cctype>
#include <filesystem>

namespace tlab::stimuli {

std::string shortName(const std::string& source) {
  std::string name = source.rfind("builtin:", 0) == 0 ? source.substr(8, source.find('?') - 8) : std::filesystem::path(source).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '-';
  return name;
}

std::string sceneName(const SceneEntry& scene) { return scene.name.empty() ? shortName(scene.source) : scene.name; }

std::string viewName(const SceneEntry& scene, std::size_t view) {
  if (!scene.views[view].name.empty()) return scene.views[view].name;
  std::string name = "v";
  return name.append(std::to_string(view + 1));
}

std::string imagesPathFor(const std::string& pattern, const SceneEntry& scene, std::size_t view) {
  std::string path = pattern;
  for (const auto& [key, value] : {std::pair{std::string("{scene}"), sceneName(scene)}, std::pair{std::string("{view}"), viewName(scene, view)}})
    for (auto p = path.find(key); p != std::string::npos; p = path.find(key, p + value.size())) path.replace(p, key.size(), value);
  return path;
}

}  // namespace tlab::stimuli
