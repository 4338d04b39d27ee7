#include "renderer/ops/silhouette_edges.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace tlab::render {

namespace {

// Welds positions closer than `tolerance`. Cells are 4 tolerances wide, so a point looks into a
// neighbour cell only along the axes where it lies within the tolerance of the cell's face.
std::vector<std::uint32_t> weld(const std::vector<glm::vec3>& in, float tolerance, std::vector<glm::vec3>& out) {
  const float cell = 4.0f * tolerance;
  const auto key = [](glm::ivec3 c) {
    return (std::uint64_t(std::uint32_t(c.x) & 0x1FFFFF) << 42) | (std::uint64_t(std::uint32_t(c.y) & 0x1FFFFF) << 21) |
           std::uint64_t(std::uint32_t(c.z) & 0x1FFFFF);
  };
  std::unordered_multimap<std::uint64_t, std::uint32_t> grid;
  grid.reserve(in.size());
  std::vector<std::uint32_t> map(in.size());
  for (std::size_t v = 0; v < in.size(); ++v) {
    const glm::vec3 g = in[v] / cell;
    const glm::ivec3 c(glm::floor(g));
    const glm::vec3 f = g - glm::vec3(c);
    glm::ivec3 lo(0), hi(0);  // neighbour offsets worth visiting per axis
    for (int a = 0; a < 3; ++a) {
      if (f[a] < 0.25f) lo[a] = -1;
      if (f[a] > 0.75f) hi[a] = 1;
    }
    std::uint32_t found = kNoFace;
    for (int dz = lo.z; dz <= hi.z && found == kNoFace; ++dz)
      for (int dy = lo.y; dy <= hi.y && found == kNoFace; ++dy)
        for (int dx = lo.x; dx <= hi.x && found == kNoFace; ++dx) {
          const auto range = grid.equal_range(key(c + glm::ivec3(dx, dy, dz)));
          for (auto it = range.first; it != range.second; ++it)
            if (glm::length(out[it->second] - in[v]) <= tolerance) {
              found = it->second;
              break;
            }
        }
    if (found == kNoFace) {
      found = static_cast<std::uint32_t>(out.size());
      out.push_back(in[v]);
      grid.emplace(key(c), found);
    }
    map[v] = found;
  }
  return map;
}

}  // namespace

EdgeAdjacency::EdgeAdjacency(const TriangleMesh& mesh, float relativeTolerance) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const float diagonal = mesh.positions.empty() ? 1.0f : glm::length(hi - lo);
  weldedIndex_ = weld(mesh.positions, std::max(diagonal * relativeTolerance, 1e-12f), positions_);
  const auto& map = weldedIndex_;
  std::unordered_map<std::uint64_t, std::uint32_t> edgeIndex;
  edgeIndex.reserve(mesh.triangles.size() * 2);
  for (const auto& t : mesh.triangles) {
    const std::array<std::uint32_t, 3> w = {map[t[0]], map[t[1]], map[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;  // collapsed by welding
    const glm::vec3 n = glm::cross(positions_[w[1]] - positions_[w[0]], positions_[w[2]] - positions_[w[0]]);
    const float length = glm::length(n);
    if (length == 0.0f) continue;
    const auto face = static_cast<std::uint32_t>(faceNormals_.size());
    faceNormals_.push_back(n / length);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = std::min(w[k], w[(k + 1) % 3]), b = std::max(w[k], w[(k + 1) % 3]);
      const std::uint64_t id = (std::uint64_t(a) << 32) | b;
      const auto [it, inserted] = edgeIndex.emplace(id, static_cast<std::uint32_t>(edges_.size()));
      if (inserted) edges_.push_back({a, b, face, kNoFace});
      else if (edges_[it->second].face1 == kNoFace) edges_[it->second].face1 = face;
      // A third face on one edge (non-manifold) adds nothing: the first two decide.
    }
  }
}

std::vector<SilhouetteSegment> EdgeAdjacency::silhouettes(glm::vec3 eye) const {
  std::vector<SilhouetteSegment> out;
  for (const auto& e : edges_) {
    const glm::vec3 p = positions_[e.a], q = positions_[e.b];
    bool silhouette = e.face1 == kNoFace;
    if (!silhouette) {
      const glm::vec3 toEdge = 0.5f * (p + q) - eye;
      silhouette = glm::dot(faceNormals_[e.face0], toEdge) * glm::dot(faceNormals_[e.face1], toEdge) < 0.0f;  // Eq. 1
    }
    if (silhouette) out.push_back({p, q});
  }
  return out;
}

}  // namespace tlab::render
