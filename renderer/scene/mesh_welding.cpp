#include "renderer/scene/mesh_welding.hpp"

#include <algorithm>
#include <tuple>
#include <unordered_map>

namespace tlab::render {

// Cells are 4 tolerances wide, so a point looks into a neighbour cell only along the axes where
// it lies within the tolerance of the cell's face.
template <typename T>
WeldedPositions<T> weldPositions(const std::vector<glm::vec3>& in, T tolerance) {
  using Vec = glm::vec<3, T>;
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  const T cell = T(4) * tolerance;
  const auto key = [](glm::ivec3 c) {
    return (std::uint64_t(std::uint32_t(c.x) & 0x1FFFFF) << 42) | (std::uint64_t(std::uint32_t(c.y) & 0x1FFFFF) << 21) |
           std::uint64_t(std::uint32_t(c.z) & 0x1FFFFF);
  };
  std::unordered_multimap<std::uint64_t, std::uint32_t> grid;
  grid.reserve(in.size());
  WeldedPositions<T> out;
  out.index.resize(in.size());
  for (std::size_t v = 0; v < in.size(); ++v) {
    const Vec p(in[v]);
    const Vec g = p / cell;
    const glm::ivec3 c(glm::floor(g));
    const Vec f = g - Vec(c);
    glm::ivec3 lo(0), hi(0);  // neighbour offsets worth visiting per axis
    for (int a = 0; a < 3; ++a) {
      if (f[a] < T(0.25)) lo[a] = -1;
      if (f[a] > T(0.75)) hi[a] = 1;
    }
    std::uint32_t found = kNone;
    for (int dz = lo.z; dz <= hi.z && found == kNone; ++dz)
      for (int dy = lo.y; dy <= hi.y && found == kNone; ++dy)
        for (int dx = lo.x; dx <= hi.x && found == kNone; ++dx) {
          const auto range = grid.equal_range(key(c + glm::ivec3(dx, dy, dz)));
          for (auto it = range.first; it != range.second; ++it)
            if (glm::length(out.positions[it->second] - p) <= tolerance) {
              found = it->second;
              break;
            }
        }
    if (found == kNone) {
      found = static_cast<std::uint32_t>(out.positions.size());
      out.positions.push_back(p);
      grid.emplace(key(c), found);
    }
    out.index[v] = found;
  }
  return out;
}

template WeldedPositions<float> weldPositions<float>(const std::vector<glm::vec3>&, float);
template WeldedPositions<double> weldPositions<double>(const std::vector<glm::vec3>&, double);

std::vector<TriangleEdge> triangleEdges(const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  struct HalfEdge {
    std::uint32_t lo, hi, triangle;
    bool forward;
  };
  std::vector<HalfEdge> halves;
  halves.reserve(triangles.size() * 3);
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
      halves.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(halves.begin(), halves.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
  });
  std::vector<TriangleEdge> edges;
  for (std::size_t i = 0; i < halves.size();) {
    TriangleEdge e;
    e.v0 = halves[i].lo;
    e.v1 = halves[i].hi;
    e.firstRunsForward = halves[i].forward;
    std::size_t j = i;
    for (; j < halves.size() && halves[j].lo == e.v0 && halves[j].hi == e.v1; ++j) e.triangles.push_back(halves[j].triangle);
    edges.push_back(std::move(e));
    i = j;
  }
  return edges;
}

}  // namespace tlab::render
