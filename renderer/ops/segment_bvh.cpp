#include "renderer/ops/segment_bvh.hpp"

#include <algorithm>
#include <cmath>

namespace tlab::render {

namespace {
constexpr std::uint32_t kLeafSize = 4;

float boxDistance(glm::vec3 p, glm::vec3 lo, glm::vec3 hi) {
  return glm::length(glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f)));
}
}  // namespace

float segmentDistance(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
  const glm::vec3 e = b - a;
  const float ee = glm::dot(e, e);
  const float t = ee > 0.0f ? glm::clamp(glm::dot(p - a, e) / ee, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * e));
}

SegmentBvh::SegmentBvh(std::vector<SilhouetteSegment> segments) : segments_(std::move(segments)) {
  if (!segments_.empty()) {
    nodes_.reserve(2 * segments_.size() / kLeafSize + 2);
    build(0, static_cast<std::uint32_t>(segments_.size()));
  }
}

// Median split of the segments' midpoints along the widest axis of their bounds.
std::uint32_t SegmentBvh::build(std::uint32_t first, std::uint32_t count) {
  Node node{glm::vec3(INFINITY), glm::vec3(-INFINITY), first, count, 0, 0};
  for (std::uint32_t i = first; i < first + count; ++i) {
    node.lo = glm::min(node.lo, glm::min(segments_[i].p0, segments_[i].p1));
    node.hi = glm::max(node.hi, glm::max(segments_[i].p0, segments_[i].p1));
  }
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(node);
  if (count <= kLeafSize) return index;
  const glm::vec3 extent = node.hi - node.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const auto begin = segments_.begin() + first, middle = begin + count / 2, end = begin + count;
  std::nth_element(begin, middle, end, [axis](const SilhouetteSegment& a, const SilhouetteSegment& b) {
    return a.p0[axis] + a.p1[axis] < b.p0[axis] + b.p1[axis];
  });
  const std::uint32_t left = build(first, count / 2);
  const std::uint32_t right = build(first + count / 2, count - count / 2);
  nodes_[index].count = 0;
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

float SegmentBvh::nearestDistance(glm::vec3 p, float limit) const {
  float best = limit;
  if (nodes_.empty()) return best;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (boxDistance(p, n.lo, n.hi) >= best) continue;
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
        best = std::min(best, segmentDistance(p, segments_[i].p0, segments_[i].p1));
      continue;
    }
    // Visit the nearer child first (pushed last).
    const Node& l = nodes_[n.left];
    const Node& r = nodes_[n.right];
    const bool leftNearer = boxDistance(p, l.lo, l.hi) <= boxDistance(p, r.lo, r.hi);
    stack[top++] = leftNearer ? n.right : n.left;
    stack[top++] = leftNearer ? n.left : n.right;
  }
  return best;
}

}  // namespace tlab::render
