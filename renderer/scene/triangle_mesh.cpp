#include "renderer/scene/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace tlab::render {

void computeVertexNormals(TriangleMesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
  for (const auto& t : mesh.triangles) {
    const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const glm::vec3 n = glm::cross(b - a, c - a);  // length = 2 * area: area weighting
    for (auto v : t) mesh.normals[v] += n;
  }
  for (auto& n : mesh.normals) {
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

namespace {

struct DisjointSets {
  std::vector<std::uint32_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

std::vector<std::uint32_t> connectedComponents(const TriangleMesh& mesh) {
  const std::size_t n = mesh.positions.size();
  DisjointSets sets(n);
  for (const auto& t : mesh.triangles) {
    sets.unite(t[0], t[1]);
    sets.unite(t[1], t[2]);
  }
  // Weld coincident vertices: quantise positions to a grid 1e-6 of the bounding box size.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const auto& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const float extent = n ? std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-30f}) : 1.0f;
  const double cell = extent * 1e-6;
  std::map<std::tuple<long long, long long, long long>, std::uint32_t> firstAt;
  for (std::uint32_t v = 0; v < n; ++v) {
    const auto& p = mesh.positions[v];
    const auto key = std::make_tuple(std::llround(p.x / cell), std::llround(p.y / cell), std::llround(p.z / cell));
    const auto [it, inserted] = firstAt.emplace(key, v);
    if (!inserted) sets.unite(it->second, v);
  }
  // Number components densely in order of their smallest vertex: deterministic.
  std::vector<std::uint32_t> id(n);
  std::map<std::uint32_t, std::uint32_t> dense;
  for (std::uint32_t v = 0; v < n; ++v) {
    const auto root = sets.find(v);
    const auto [it, inserted] = dense.emplace(root, static_cast<std::uint32_t>(dense.size()));
    id[v] = it->second;
  }
  return id;
}

void transformMesh(TriangleMesh& mesh, const glm::mat4& transform) {
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  for (auto& p : mesh.positions) p = glm::vec3(transform * glm::vec4(p, 1.0f));
  for (auto& n : mesh.normals) {
    const glm::vec3 m = normalMatrix * n;
    const float len = glm::length(m);
    n = len > 0.0f ? m / len : n;
  }
  // A mirroring transform flips the winding; keep front faces front.
  if (glm::determinant(glm::mat3(transform)) < 0.0f)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

void appendMesh(TriangleMesh& mesh, const TriangleMesh& other) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), other.positions.begin(), other.positions.end());
  mesh.normals.insert(mesh.normals.end(), other.normals.begin(), other.normals.end());
  mesh.st.insert(mesh.st.end(), other.st.begin(), other.st.end());
  for (auto t : other.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

}  // namespace tlab::render
