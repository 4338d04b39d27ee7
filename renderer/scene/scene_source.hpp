#pragma once
// Where a scene comes from: `builtin:NAME[?param=value&...]` or a glTF (.gltf/.glb) path.
#include <string>
#include <vector>

#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::render {

// `catalog` lists the built-in scenes available (the renderer's own plus any added by later
// libraries). Throws with a one-line message naming the scene source.
Scene loadScene(const std::string& source, const std::vector<BuiltinSceneSpec>& catalog = builtinScenes());

// The checks loadScene makes before the expensive work: a built-in's name and parameters, or a
// glTF file that exists and loads. Throws the same one-line messages.
void checkSceneSource(const std::string& source, const std::vector<BuiltinSceneSpec>& catalog = builtinScenes());

}  // namespace tlab::render
