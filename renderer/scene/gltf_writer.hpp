#pragma once
// Writes a scene as glTF 2.0 (binary .glb, or .gltf with the buffer embedded) so another renderer
// (Blender, ParaView, VTK) can draw the view tlab draws: one mesh per object (world-space
// positions, normals, indices; baseColorFactor = the front colour), the object's roles, group and
// back colour in its node's extras, and a perspective camera node placed exactly where tlab's
// camera is (eye at the node's origin looking down −Z with +Y up; yfov, aspectRatio = W/H, znear,
// zfar). The scene's extras hold the background, the image size and the camera as tlab names it.
#include <string>

#include "renderer/scene/scene.hpp"

namespace tlab::render {

void writeGltfFile(const Scene& scene, const Camera& camera, int width, int height, const std::string& path);

// The names of the roles set in `roles` ("transparent", "opaque", "target", "distractor",
// "impenetrable").
std::vector<std::string> roleNames(Role roles);

}  // namespace tlab::render
