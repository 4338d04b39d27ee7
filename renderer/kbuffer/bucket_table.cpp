#include "renderer/kbuffer/bucket_table.hpp"

#include <algorithm>
#include <cmath>

namespace tlab::render::kbuffer {

std::uint32_t packDepthFirst(std::uint16_t depth, std::uint16_t shape) { return (std::uint32_t(depth) << 16) | shape; }
std::uint32_t packShapeFirst(std::uint16_t depth, std::uint16_t shape) { return (std::uint32_t(shape) << 16) | depth; }
std::uint32_t swapHalves(std::uint32_t key) { return (key << 16) | (key >> 16); }
std::uint16_t shapeOfShapeFirst(std::uint32_t key) { return std::uint16_t(key >> 16); }
std::uint16_t depthOfShapeFirst(std::uint32_t key) { return std::uint16_t(key & 0xFFFFu); }

std::uint16_t quantizeDepth(float depth01) {
  return std::uint16_t(std::lround(std::clamp(depth01, 0.0f, 1.0f) * 65535.0f));
}
float depthOf16(std::uint16_t depth) { return float(depth) / 65535.0f; }

std::uint32_t packBucket(const Bucket& b) { return (std::uint32_t(b.shape) << 16) | (b.first << 8) | b.last; }
Bucket unpackBucket(std::uint32_t word) {
  return Bucket{std::uint16_t(word >> 16), (word >> 8) & 0xFFu, word & 0xFFu};
}

void insertNearest(std::span<std::uint32_t> z, std::uint32_t key) {
  // Each step is one atomicMin: the slot keeps the smaller key, the larger one moves on.
  for (auto& slot : z) {
    const std::uint32_t old = slot;
    slot = std::min(old, key);
    key = std::max(old, key);
    if (key == kEmpty) return;
  }
}

std::uint32_t buildBuckets(std::span<std::uint32_t> z, std::span<std::uint32_t> table) {
  std::uint32_t n = 0;
  while (n < z.size() && z[n] != kEmpty) ++n;
  for (std::uint32_t i = 0; i < n; ++i) z[i] = swapHalves(z[i]);
  std::sort(z.begin(), z.begin() + n);
  std::fill(table.begin(), table.end(), kEmpty);
  const auto k = static_cast<std::uint32_t>(table.size());
  for (std::uint32_t i = 0; i < n;) {
    const std::uint16_t b = shapeOfShapeFirst(z[i]);
    std::uint32_t j = i;
    while (j + 1 < n && shapeOfShapeFirst(z[j + 1]) == b) ++j;
    std::uint32_t slot = b % k;                             // H(b) = b mod k
    while (table[slot] != kEmpty) slot = (slot + 1) % k;    // "b is incremented until H(b) is free"
    table[slot] = packBucket({b, i, j});
    i = j + 1;
  }
  return n;
}

std::optional<std::uint32_t> findBucketSlot(std::span<const std::uint32_t> table, std::uint16_t shape) {
  const auto k = static_cast<std::uint32_t>(table.size());
  for (std::uint32_t probe = 0, slot = shape % k; probe < k; ++probe, slot = (slot + 1) % k) {
    if (table[slot] == kEmpty) return std::nullopt;
    if (unpackBucket(table[slot]).shape == shape) return slot;
  }
  return std::nullopt;
}

std::optional<Bucket> findBucket(std::span<const std::uint32_t> table, std::uint16_t shape) {
  const auto slot = findBucketSlot(table, shape);
  if (!slot) return std::nullopt;
  return unpackBucket(table[*slot]);
}

std::optional<std::uint32_t> findInBucket(std::span<const std::uint32_t> z, const Bucket& bucket, std::uint32_t key) {
  std::uint32_t lo = bucket.first, hi = bucket.last + 1;  // lower bound in [first, last + 1)
  while (lo < hi) {
    const std::uint32_t mid = (lo + hi) / 2;
    if (z[mid] < key) lo = mid + 1;
    else hi = mid;
  }
  if (lo <= bucket.last && z[lo] == key) return lo;
  return std::nullopt;
}

float continuity(const QueryFragment& a, const QueryFragment& b) {
  const float epsN = 1.0f - glm::dot(a.normal, b.normal);  // seed 002, Sec. 5.1, εn
  const float dz = depthOf16(depthOfShapeFirst(a.key)) - depthOf16(depthOfShapeFirst(b.key));
  const float epsZ = dz * dz;                              // εz
  return epsN + epsZ;                                      // ε = εn + εz
}

std::optional<std::uint32_t> bestCandidate(const QueryFragment& f, const ReferencePixel& q, NeighborSearch search) {
  const std::uint16_t shape = shapeOfShapeFirst(f.key);
  std::uint32_t first = 0, last = 0;
  if (search == NeighborSearch::Buckets) {
    const auto bucket = findBucket(q.table, shape);
    if (!bucket) return std::nullopt;
    first = bucket->first;
    last = bucket->last + 1;
  } else {
    last = static_cast<std::uint32_t>(q.fragments.size());
  }
  std::optional<std::uint32_t> best;
  float bestEps = INFINITY;
  for (std::uint32_t j = first; j < last; ++j) {
    if (shapeOfShapeFirst(q.fragments[j].key) != shape) continue;
    const float e = continuity(f, q.fragments[j]);
    if (e < bestEps) {
      bestEps = e;
      best = j;
    }
  }
  return best;
}

std::optional<std::uint32_t> neighborOf(const ReferencePixel& p, std::uint32_t i, const ReferencePixel& q,
                                        NeighborSearch search) {
  const auto j = bestCandidate(p.fragments[i], q, search);
  if (!j) return std::nullopt;
  const auto back = bestCandidate(q.fragments[*j], p, search);  // Fig. 5: the reverse check
  if (!back || *back != i) return std::nullopt;
  return j;
}

float screenSpaceCurvature(const std::optional<glm::vec3>& left, const std::optional<glm::vec3>& right,
                           const std::optional<glm::vec3>& down, const std::optional<glm::vec3>& up, float scale) {
  if (!left || !right || !down || !up) return -1.0f;  // Sec. 5.1: a missing neighbour
  const float divergence = 0.5f * (right->x - left->x) + 0.5f * (up->y - down->y);
  return std::tanh(-scale * divergence);  // Sec. 5.1: κ = tanh(κ1 + κ2)
}

}  // namespace tlab::render::kbuffer
