#pragma once
// A Scene uploaded for rasterization: one merged vertex/index buffer (so gl_PrimitiveID is a
// global triangle index, the deterministic tie-break of the sort) and a table of per-object
// records (colours, roles, group, component id offset).
#include <cstdint>
#include <optional>

#include "renderer/gpu/gl_objects.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::render {

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);
  void bindObjectTable() const;  // binds the object table at BIND_OBJECTS
  void draw() const;             // one draw call for all triangles
  std::size_t triangleCount() const { return triangleCount_; }
  std::uint32_t componentCount() const { return componentCount_; }
  // The scene's box at upload (Scene::boundingBox), for the passes that need it every frame.
  const std::optional<BoundingBox>& bounds() const { return bounds_; }

 private:
  gpu::VertexArray vao_;
  gpu::Buffer positions_, normals_, st_, objectIds_, componentIds_, indices_, objectTable_;
  std::size_t triangleCount_ = 0;
  std::uint32_t componentCount_ = 0;
  std::optional<BoundingBox> bounds_;
};

}  // namespace tlab::render
