#pragma once
// The back-to-front drawing order of dynamic transparency (Elmqvist et al., seed 004, Sec. V.2,
// Alg. 1 line 1). Objects form groups: by default one object per group; objects sharing a
// SceneObject::group id ≥ 0 form one group drawn in a fixed internal order (their order of
// appearance in the scene — innermost Russian doll first). Groups are sorted by the signed
// distance of their precomputed centre from the eye along the view vector, farthest first, with
// a bubble sort that starts from the previous frame's order (frame coherence: a still or slowly
// moving camera costs O(n)). Impenetrable objects are drawn before everything else (Sec. V.2:
// "rendered to the frame buffer first"), each as its own group.
//
// A value object: whoever renders successive frames (the Renderer) owns one and calls update()
// once per frame.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.hpp"

namespace tlab::render {

class GroupDrawOrder {
 public:
  GroupDrawOrder() = default;
  explicit GroupDrawOrder(const Scene& scene);

  // Re-sorts for a camera at `eye` looking along `viewDirection`; returns the number of swaps
  // the bubble sort made (0 when the previous order still holds).
  std::size_t update(glm::vec3 eye, glm::vec3 viewDirection);

  // rank[o]: the position of object o in the drawing order (0 = drawn first).
  std::vector<std::uint32_t> objectRanks() const;
  // The groups in drawing order, each as its object indices in their fixed internal order.
  std::vector<std::vector<std::uint32_t>> groupsInDrawOrder() const;
  std::size_t groupCount() const { return groups_.size(); }
  std::size_t objectCount() const { return objectCount_; }

 private:
  struct Group {
    std::vector<std::uint32_t> objects;  // fixed internal order
    glm::vec3 centre{0.0f};              // precomputed once
    bool impenetrable = false;           // drawn before all other groups
  };
  std::vector<Group> groups_;
  std::vector<std::size_t> order_;  // indices into groups_, drawing order
  std::size_t objectCount_ = 0;
};

}  // namespace tlab::render
