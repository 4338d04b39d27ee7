#pragma once
// What a style derives from the scene alone (edge adjacency, uploaded meshes), built on the first
// frame that asks and kept for the renderer's life: a renderer's scene never changes, so a
// style's passes need not rebuild it every frame (issue #29: the view-dependent style rebuilt its
// edge adjacency of the whole mesh for every frame). Also what a style keeps across frames beside
// it (the raster styles' targets, which re-make themselves when the frame's size changes). One
// object per type; T is constructed from the scene. Owned by the renderer, next to the GL context
// its objects' buffers belong to.
#include <memory>
#include <typeindex>
#include <unordered_map>

#include "renderer/scene/scene.hpp"

namespace tlab::render {

class SceneCache {
 public:
  // The T derived from `scene`, built by T(scene) on the first call.
  template <typename T>
  T& get(const Scene& scene) {
    std::shared_ptr<void>& slot = items_[std::type_index(typeid(T))];
    if (!slot) slot = std::make_shared<T>(scene);
    return *static_cast<T*>(slot.get());
  }

 private:
  std::unordered_map<std::type_index, std::shared_ptr<void>> items_;  // (shared_ptr<void> deletes as T)
};

}  // namespace tlab::render
