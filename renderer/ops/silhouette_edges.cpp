#include "renderer/ops/silhouette_edges.hpp"

#include <algorithm>
#include <cmath>
#include <map>
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
  std::vector<std::array<std::uint32_t, 3>> faces;
  edgeIndex.reserve(mesh.triangles.size() * 2);
  for (const auto& t : mesh.triangles) {
    const std::array<std::uint32_t, 3> w = {map[t[0]], map[t[1]], map[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;  // collapsed by welding
    const glm::vec3 n = glm::cross(positions_[w[1]] - positions_[w[0]], positions_[w[2]] - positions_[w[0]]);
    const float length = glm::length(n);
    if (length == 0.0f) continue;
    const auto face = static_cast<std::uint32_t>(faceNormals_.size());
    faceNormals_.push_back(n / length);
    faces.push_back(w);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = std::min(w[k], w[(k + 1) % 3]), b = std::max(w[k], w[(k + 1) % 3]);
      const std::uint64_t id = (std::uint64_t(a) << 32) | b;
      const auto [it, inserted] = edgeIndex.emplace(id, static_cast<std::uint32_t>(edges_.size()));
      if (inserted) edges_.push_back({a, b, face, kNoFace});
      else if (edges_[it->second].face1 == kNoFace) edges_[it->second].face1 = face;
      // A third face on one edge (non-manifold) adds nothing: the first two decide.
    }
  }
  faces_ = std::move(faces);
  findBuriedEdges();
}

namespace {

// Union-find root with path halving.
std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t f) {
  while (parent[f] != f) f = parent[f] = parent[parent[f]];
  return f;
}

// Möller-Trumbore: does the ray o + t·d (t > 0) cross triangle (a, b, c)?
bool rayCrosses(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 e1 = b - a, e2 = c - a, h = glm::cross(d, e2);
  const float det = glm::dot(e1, h);
  if (std::abs(det) < 1e-12f) return false;
  const glm::vec3 s = o - a;
  const float u = glm::dot(s, h) / det, v = glm::dot(d, glm::cross(s, e1)) / det;
  return u >= 0.0f && v >= 0.0f && u + v <= 1.0f && glm::dot(e2, glm::cross(s, e1)) / det > 0.0f;
}

}  // namespace

// Parts = face components joined by shared edges; a closed part has no boundary edge. An edge
// is buried when its midpoint is inside another closed part (odd number of crossings of a ray in
// a direction no mesh is aligned with).
void EdgeAdjacency::findBuriedEdges() {
  const auto faceCount = static_cast<std::uint32_t>(faces_.size());
  std::vector<std::uint32_t> parent(faceCount);
  for (std::uint32_t f = 0; f < faceCount; ++f) parent[f] = f;
  for (const auto& e : edges_)
    if (e.face1 != kNoFace) parent[root(parent, e.face0)] = root(parent, e.face1);
  struct Part {
    bool closed = true;
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
  };
  std::map<std::uint32_t, Part> parts;
  for (std::uint32_t f = 0; f < faceCount; ++f) {
    Part& p = parts[root(parent, f)];
    for (std::uint32_t v : faces_[f]) {
      p.lo = glm::min(p.lo, positions_[v]);
      p.hi = glm::max(p.hi, positions_[v]);
    }
  }
  for (const auto& e : edges_)
    if (e.face1 == kNoFace) parts[root(parent, e.face0)].closed = false;
  buried_.assign(edges_.size(), false);
  if (parts.size() < 2) return;
  const glm::vec3 direction = glm::normalize(glm::vec3(0.5773f, 0.6137f, 0.5383f));
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const std::uint32_t own = root(parent, edges_[i].face0);
    const glm::vec3 m = 0.5f * (positions_[edges_[i].a] + positions_[edges_[i].b]);
    std::map<std::uint32_t, int> crossings;
    const auto around = [&](const Part& p) { return glm::all(glm::lessThan(p.lo, m)) && glm::all(glm::lessThan(m, p.hi)); };
    bool any = false;
    for (const auto& [id, p] : parts) any = any || (id != own && p.closed && around(p));
    if (!any) continue;
    for (std::uint32_t f = 0; f < faceCount; ++f) {
      const std::uint32_t part = root(parent, f);
      if (part == own || !parts[part].closed || !around(parts[part])) continue;
      const auto& t = faces_[f];
      if (rayCrosses(m, direction, positions_[t[0]], positions_[t[1]], positions_[t[2]])) ++crossings[part];
    }
    for (const auto& [part, n] : crossings) buried_[i] = buried_[i] || (n % 2 == 1);
  }
}


std::vector<SilhouetteSegment> EdgeAdjacency::silhouettes(glm::vec3 eye) const {
  std::vector<SilhouetteSegment> out;
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    if (buried_[i]) continue;
    const MeshEdge& e = edges_[i];
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
