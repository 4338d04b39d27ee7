#include "renderer/peel/layered_grid_scene.hpp"

#include "renderer/scene/builtin_scenes.hpp"

#include <cmath>
#include <stdexcept>

namespace tlab::render {

namespace {

// A (cells x cells) grid over [-h, h]² at depth z, counter-clockwise towards +z.
TriangleMesh makeGridQuad(float h, float z, int cells) {
  TriangleMesh m;
  for (int r = 0; r <= cells; ++r)
    for (int c = 0; c <= cells; ++c) {
      const glm::vec2 st(float(c) / float(cells), float(r) / float(cells));
      m.positions.emplace_back(-h + 2.0f * h * st.x, -h + 2.0f * h * st.y, z);
      m.normals.emplace_back(0.0f, 0.0f, 1.0f);
      m.st.push_back(st);
    }
  appendGridTriangles(m, cells, cells);
  return m;
}

}  // namespace

Scene makeLayeredGridScene(int layers, std::size_t minTriangles) {
  if (layers < 1) throw std::invalid_argument("the layered grid scene needs at least one layer");
  const int cells = std::max(1, static_cast<int>(std::ceil(std::sqrt(double(minTriangles) / (2.0 * layers)))));
  Scene s;
  s.name = "layered-grid";
  SceneObject o;
  o.name = "layers";
  o.roles = Role::Transparent;
  for (int i = 0; i < layers; ++i) appendMesh(o.mesh, makeGridQuad(4.0f, -1.0f + 2.0f * (float(i) + 0.5f) / float(layers), cells));
  s.objects.push_back(std::move(o));
  Camera c;
  c.eye = {0.0f, 0.0f, 5.0f};
  c.target = {0.0f, 0.0f, 0.0f};
  c.nearPlane = 1.0f;
  c.farPlane = 10.0f;
  s.camera = c;
  return s;
}

}  // namespace tlab::render
