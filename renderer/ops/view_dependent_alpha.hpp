#pragma once
// View-dependent transparency of Diepstraten et al. 2002 (Sec. 5): per view, the object-space
// silhouette edges of every object (Eq. 1, ops/silhouette_edges), then per vertex of each
// transparent object the minimum distance d_min to its own silhouette edges and
// α = 1 − (d_min / d_object,max)^k (Eq. 2). The distance loop — the part the paper found
// dominant, O(vertices × silhouette edges) done plainly — queries a BVH over the silhouette edges
// (ops/segment_bvh) in a parallel loop over the vertices.
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gpu/gl_objects.hpp"
#include "renderer/ops/silhouette_edges.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::render {

class ViewDependentAlpha {
 public:
  // Builds the adjacency of every object and uploads the merged mesh in GpuScene's order (so a
  // fragment's global triangle index finds its vertices).
  explicit ViewDependentAlpha(const Scene& scene);

  // Silhouettes for `eye` (world space) and the per-vertex α of Eq. 2 with fall-off `k`,
  // uploaded for the compositor.
  void update(glm::vec3 eye, float k);

  // The silhouette edges of the last update(), all objects, world space; and which of them
  // belong to transparent objects (segments_[i] for i in [0, transparentCount()) are those).
  const std::vector<SilhouetteSegment>& silhouettes() const { return segments_; }
  std::size_t transparentCount() const { return transparentCount_; }
  // Per merged vertex α (1 for opaque objects); vertex positions (vec4, world) and triangles (3
  // indices each) of the merged mesh.
  const gpu::Buffer& vertexAlpha() const { return vertexAlpha_; }
  const gpu::Buffer& positions() const { return positions_; }
  const gpu::Buffer& triangles() const { return triangles_; }
  const std::vector<float>& vertexAlphaValues() const { return alpha_; }

 private:
  struct ObjectEdges {
    EdgeAdjacency adjacency;
    float maxDistance;  // d_object,max: largest distance from the centre to a vertex
    bool transparent;
  };
  std::vector<ObjectEdges> objects_;
  std::vector<SilhouetteSegment> segments_;
  std::size_t transparentCount_ = 0;
  std::vector<float> alpha_;
  gpu::Buffer positions_, triangles_, vertexAlpha_;
};

}  // namespace tlab::render
