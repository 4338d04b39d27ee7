#pragma once
// The depth-complexity scene of `tlab bench peel`: L parallel full-screen quads at distinct
// depths (every pixel sees exactly L layers, as the quad stack of Murray Sec. 6), each a regular
// grid fine enough that the scene has at least `minTriangles` triangles.
#include <cstddef>

#include "renderer/scene/scene.hpp"

namespace tlab::render {

Scene makeLayeredGridScene(int layers, std::size_t minTriangles);

}  // namespace tlab::render
