#pragma once
#include "renderer/pipeline/frame_context.hpp"

namespace tlab::render {

// Rasterizes the scene with the z-buffer into a float colour target and reads it back.
class OpaqueRasterPass final : public RenderPass {
 public:
  std::string name() const override { return "raster"; }
  void run(FrameContext& frame) override;
};

}  // namespace tlab::render
