#pragma once
// The picture flow with depth peeling instead of the illustration buffer: Scene → (peel, blend)ⁿ
// → Image, for the local styles (`constant`, `angle`, `normal-variation`, `iris`). Takes the same
// RenderRequest as Renderer so the two can be compared frame for frame (`tlab bench peel`).
#include <memory>

#include "renderer/peel/depth_peeler.hpp"
#include "renderer/pipeline/renderer.hpp"

namespace tlab::render {

struct PeelStats {
  int iterations = 0;  // layers + 1
  std::vector<std::pair<std::string, double>> passMilliseconds;
  Camera camera;
};

class PeelingRenderer {
 public:
  // Uploads the scene; a GpuContext must be current.
  explicit PeelingRenderer(Scene scene);
  const Scene& scene() const { return scene_; }
  // request.fill, initialPoolFragments and allProperties do not apply.
  core::Image render(const RenderRequest& request, PeelStats* stats = nullptr);

 private:
  Scene scene_;
  GpuScene gpuScene_;
  gpu::ShaderCache shaders_;
  std::unique_ptr<DepthPeeler> peeler_;
};

}  // namespace tlab::render
