#include "renderer/ops/view_dependent_alpha.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "core/parallel_shares.hpp"
#include "renderer/gpu/gl_error.hpp"
#include "renderer/ops/segment_bvh.hpp"

namespace tlab::render {

namespace {

template <typename T>
gpu::Buffer upload(const std::vector<T>& v) {
  // Zero-sized buffers cannot be bound: keep at least one element.
  return v.empty() ? gpu::Buffer(sizeof(T)) : gpu::Buffer(v.size() * sizeof(T), v.data());
}

float maxDistanceFromCentre(const TriangleMesh& mesh) {
  glm::vec3 centre(0.0f);
  for (const auto& p : mesh.positions) centre += p / float(std::max<std::size_t>(mesh.positions.size(), 1));
  float d = 0.0f;
  for (const auto& p : mesh.positions) d = std::max(d, glm::length(p - centre));
  return std::max(d, 1e-12f);
}

// Runs body(i) for i in [0, n) on every hardware thread (up to 64), in shares of at least 4096.
template <typename F>
void parallelFor(std::size_t n, F&& body) {
  const unsigned threads = std::min(std::thread::hardware_concurrency(), 64u);
  core::forEachShare(n, core::sharesFor(n, 4096, threads), [&](std::size_t from, std::size_t to, std::size_t) {
    for (std::size_t i = from; i < to; ++i) body(i);
  });
}

}  // namespace

ViewDependentAlpha::ViewDependentAlpha(const Scene& scene) {
  std::vector<glm::vec4> positions;
  std::vector<std::uint32_t> triangles;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const auto& object = scene.objects[o];
    const auto base = static_cast<std::uint32_t>(positions.size());
    for (const auto& p : object.mesh.positions) positions.emplace_back(p, 1.0f);
    for (const auto& t : object.mesh.triangles) triangles.insert(triangles.end(), {t[0] + base, t[1] + base, t[2] + base});
    objects_.push_back({EdgeAdjacency(object.mesh), maxDistanceFromCentre(object.mesh), !hasRole(object.roles, Role::Opaque)});
  }
  positions_ = upload(positions);
  triangles_ = upload(triangles);
  alpha_.assign(positions.size(), 1.0f);
  vertexAlpha_ = upload(alpha_);
}

void ViewDependentAlpha::update(glm::vec3 eye, float k) {
  segments_.clear();
  transparentCount_ = 0;
  std::size_t base = 0;
  for (const auto& object : objects_) {
    const auto& welded = object.adjacency.weldedIndex();
    auto segments = object.adjacency.silhouettes(eye);  // Eq. 1
    // Transparent objects' lines first, then the opaque ones' (drawn against different depths).
    if (object.transparent) {
      segments_.insert(segments_.begin() + std::ptrdiff_t(transparentCount_), segments.begin(), segments.end());
      transparentCount_ += segments.size();
    } else {
      segments_.insert(segments_.end(), segments.begin(), segments.end());
    }
    if (object.transparent) {
      // d_min per welded vertex (seams and poles once), then Eq. 2 for every copy.
      const SegmentBvh nearest(std::move(segments));
      const auto& positions = object.adjacency.positions();
      std::vector<float> weldedAlpha(positions.size());
      const float dMax = object.maxDistance;
      parallelFor(positions.size(), [&](std::size_t v) {
        const float dMin = nearest.nearestDistance(positions[v], dMax);
        weldedAlpha[v] = 1.0f - std::pow(std::clamp(dMin / dMax, 0.0f, 1.0f), k);  // Eq. 2
      });
      for (std::size_t v = 0; v < welded.size(); ++v) alpha_[base + v] = weldedAlpha[welded[v]];
    } else {
      std::fill(alpha_.begin() + std::ptrdiff_t(base), alpha_.begin() + std::ptrdiff_t(base + welded.size()), 1.0f);
    }
    base += welded.size();
  }
  vertexAlpha_.upload(alpha_.data(), alpha_.size() * sizeof(float));
  gpu::checkGl("uploading the view-dependent alpha");
}

}  // namespace tlab::render
