#pragma once
// A bounding-volume hierarchy over line segments for nearest-segment distance queries: the
// per-vertex d_min of Diepstraten Sec. 5 in O(log S) per vertex instead of O(S) — the
// distance loop the paper found to dominate its frame time.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/ops/silhouette_edges.hpp"

namespace tlab::render {

class SegmentBvh {
 public:
  explicit SegmentBvh(std::vector<SilhouetteSegment> segments);
  // The distance from `p` to the nearest segment, or `limit` when none is closer than `limit`.
  float nearestDistance(glm::vec3 p, float limit) const;
  bool empty() const { return segments_.empty(); }

 private:
  struct Node {
    glm::vec3 lo, hi;
    std::uint32_t first, count;  // leaf: segments [first, first + count); inner: count = 0
    std::uint32_t left, right;
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count);
  std::vector<SilhouetteSegment> segments_;
  std::vector<Node> nodes_;
};

// The distance from p to the segment [a, b].
float segmentDistance(glm::vec3 p, glm::vec3 a, glm::vec3 b);

}  // namespace tlab::render
