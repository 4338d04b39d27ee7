#include "renderer/scene/scene_source.hpp"

#include "renderer/scene/gltf_loader.hpp"

namespace tlab::render {

Scene loadScene(const std::string& source, const std::vector<BuiltinSceneSpec>& catalog) {
  constexpr std::string_view prefix = "builtin:";
  if (source.rfind(prefix, 0) == 0) {
    Scene scene = buildBuiltinScene(source.substr(prefix.size()), catalog);
    requireTriangles(scene, source);
    return scene;
  }
  return loadGltfFile(source);
}

void checkSceneSource(const std::string& source, const std::vector<BuiltinSceneSpec>& catalog) {
  constexpr std::string_view prefix = "builtin:";
  if (source.rfind(prefix, 0) == 0) parseBuiltinScene(source.substr(prefix.size()), catalog);
  else loadGltfFile(source);
}

}  // namespace tlab::render
