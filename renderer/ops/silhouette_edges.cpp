#include "renderer/ops/silhouette_edges.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace tlab::render {

EdgeAdjacency::EdgeAdjacency(const TriangleMesh& mesh, float relativeTolerance) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const float diagonal = mesh.positions.empty() ? 1.0f : glm::length(hi - lo);
  WeldedPositions<float> welded = weldPositions(mesh.positions, std::max(diagonal * relativeTolerance, 1e-12f));
  positions_ = std::move(welded.positions);
  weldedIndex_ = std::move(welded.index);
  const auto& map = weldedIndex_;
  for (const auto& t : mesh.triangles) {
    const std::array<std::uint32_t, 3> w = {map[t[0]], map[t[1]], map[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;  // collapsed by welding
    const glm::vec3 n = glm::cross(positions_[w[1]] - positions_[w[0]], positions_[w[2]] - positions_[w[0]]);
    const float length = glm::length(n);
    if (length == 0.0f) continue;
    faceNormals_.push_back(n / length);
    faces_.push_back(w);
  }
  collectEdges();
  findBuriedEdges();
}

// The edges in order of first appearance (face by face, each face's edges in winding order):
// silhouettes() lists its segments in this order, and the lines are drawn in it. A third face on
// one edge (non-manifold) adds nothing: the first two decide.
void EdgeAdjacency::collectEdges() {
  std::vector<std::pair<std::uint64_t, MeshEdge>> ordered;
  for (const TriangleEdge& e : triangleEdges(faces_)) {
    const std::uint32_t face = e.triangles[0];
    std::uint64_t k = 0;
    while (std::minmax(faces_[face][k], faces_[face][(k + 1) % 3]) != std::minmax(e.v0, e.v1)) ++k;
    const std::uint32_t face1 = e.triangles.size() > 1 ? e.triangles[1] : kNoFace;
    ordered.push_back({std::uint64_t(face) * 3 + k, MeshEdge{e.v0, e.v1, face, face1}});
  }
  std::sort(ordered.begin(), ordered.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  edges_.reserve(ordered.size());
  for (const auto& [order, edge] : ordered) edges_.push_back(edge);
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
