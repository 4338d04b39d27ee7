#pragma once
// glTF 2.0 (.gltf and .glb) → Scene, through tinygltf: the node hierarchy with its transforms,
// indexed or non-indexed triangles (lists, strips, fans), normals computed when missing,
// TEXCOORD_0 as (s, t), the material's base colour, and the first camera.
#include <string>
#include <vector>

#include "renderer/scene/scene.hpp"

namespace tlab::render {

// Throws std::runtime_error with a one-line message naming the file on any problem.
Scene loadGltfFile(const std::string& path);

// The same from bytes already in memory (`name` is used in messages; `binary` selects .glb).
Scene loadGltfFromMemory(const std::vector<unsigned char>& bytes, const std::string& name, bool binary,
                         const std::string& baseDir = ".");

}  // namespace tlab::render
