#pragma once
// Hand-made meshes and scenes for the task tests.
#include <string>

#include <glm/glm.hpp>

#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::tasks::testing {

// A U-shaped strip, z ∈ [0, 1]: a bottom sheet y = 0 and a top sheet y = h for x ∈ [0, length],
// joined by a wall at x = length. Developed, it is a flat strip of length 2 · length + h.
inline render::TriangleMesh makeFoldedStrip(double length, double h, int cellsAlong, int cellsAcross) {
  render::TriangleMesh m;
  const double total = 2.0 * length + h;
  const int columns = cellsAlong;
  // Development coordinate s along the strip: bottom s ∈ [0, length], wall, then top back to x = 0.
  const auto place = [&](double s, double z) -> glm::vec3 {
    if (s <= length) return {float(s), 0.0f, float(z)};
    if (s <= length + h) return {float(length), float(s - length), float(z)};
    return {float(total - s), float(h), float(z)};
  };
  // Make sure the fold lines are vertex columns: s = length and s = length + h.
  std::vector<double> ss;
  for (int i = 0; i <= columns; ++i) ss.push_back(length * i / columns);
  ss.push_back(length + h);
  for (int i = 1; i <= columns; ++i) ss.push_back(length + h + length * i / columns);
  for (std::size_t i = 0; i < ss.size(); ++i)
    for (int j = 0; j <= cellsAcross; ++j) {
      m.positions.push_back(place(ss[i], double(j) / cellsAcross));
      m.normals.push_back({0, 1, 0});
      m.st.push_back({float(ss[i] / total), float(j) / cellsAcross});
    }
  const auto idx = [&](std::size_t i, int j) { return std::uint32_t(i * (cellsAcross + 1) + j); };
  for (std::size_t i = 0; i + 1 < ss.size(); ++i)
    for (int j = 0; j < cellsAcross; ++j) {
      m.triangles.push_back({idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)});
      m.triangles.push_back({idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)});
    }
  return m;
}

inline render::SceneObject makeObject(std::string name, render::TriangleMesh mesh, render::Role roles) {
  render::SceneObject o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.roles = roles;
  return o;
}

// A small box standing on the floor at floor point (x, z).
inline render::SceneObject boxAt(std::string name, glm::dvec2 floor, render::Role roles) {
  render::TriangleMesh box = render::makeBox(glm::vec3(0.1f));
  render::transformMesh(box, glm::mat4(1.0f, 0, 0, 0, 0, 1.0f, 0, 0, 0, 0, 1.0f, 0, float(floor.x), 0.1f, float(floor.y), 1.0f));
  return makeObject(std::move(name), std::move(box), roles);
}

}  // namespace tlab::tasks::testing
