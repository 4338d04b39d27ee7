#pragma once
// A Scene uploaded for rasterization: one merged vertex/index buffer (so gl_PrimitiveID is a
// global triangle index, the deterministic tie-break of the sort) and a table of per-object
// records (colours, roles, group, component id offset).
#include <cstddef>
#include <cstdint>
#include <optional>

#include "renderer/gpu/gl_objects.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::render {

// How many runs a scene of `triangles` is drawn in by default (GpuScene::draw): where the GL runs
// on the CPU, one for every kTrianglesPerDrawRun triangles, at most kMaxDrawRuns; on a GPU one,
// since its driver pipelines a draw call itself. (llvmpipe bins all of a call's triangles on the
// calling thread before its worker threads rasterize any: on 2 cores, 25-30 ms of the 100,000-
// triangle torus's fill at 512² had one core waiting; issue #29, twenty-seventh round.)
constexpr std::size_t kTrianglesPerDrawRun = 12500, kMaxDrawRuns = 8;
std::size_t defaultDrawRuns(std::size_t triangles, bool glOnCpu);

class GpuScene {
 public:
  // Uploads the scene to the current context, and picks its draw runs: TLAB_DRAW_RUNS where set
  // (gpu::drawRunsSetting), else defaultDrawRuns for this GL.
  explicit GpuScene(const Scene& scene);
  void bindObjectTable() const;  // binds the object table at BIND_OBJECTS
  // Draws all triangles with the current program, in drawRuns() consecutive runs of about equal
  // length, each handed to the GL with glFlush: a CPU rasterizer then bins one run on this thread
  // while its worker threads rasterize the last. The GL rasterizes the runs in order, so each
  // pixel receives its fragments in the order of one call. gl_PrimitiveID restarts at 0 with
  // every call: a program that reads it offsets it by its uint uniform uPrimitiveBase
  // (buffer/fragment_record.glsl), whose location is `primitiveBase`: the draw sets it to each
  // run's first triangle (0 for one run), so no caller sets it.
  void draw(GLint primitiveBase = -1) const;
  std::size_t drawRuns() const { return runs_; }
  void setDrawRuns(std::size_t runs) { runs_ = runs < 1 ? 1 : runs; }  // tests compare 1 and more
  std::size_t triangleCount() const { return triangleCount_; }
  std::uint32_t componentCount() const { return componentCount_; }
  // The scene's box at upload (Scene::boundingBox), for the passes that need it every frame.
  const std::optional<BoundingBox>& bounds() const { return bounds_; }

 private:
  gpu::VertexArray vao_;
  gpu::Buffer positions_, normals_, st_, objectIds_, componentIds_, indices_, objectTable_;
  std::size_t triangleCount_ = 0;
  std::uint32_t componentCount_ = 0;
  std::size_t runs_ = 1;
  std::optional<BoundingBox> bounds_;
};

}  // namespace tlab::render
