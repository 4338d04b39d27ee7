#pragma once
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

// Rasterizes the scene straight into a float colour target and reads it back: with the z-buffer
// (style `opaque`) or with plain alpha blending in submission order (style `unsorted`).
class RasterPass final : public RenderPass {
 public:
  enum class Mode { ZBuffer, UnsortedBlend };
  explicit RasterPass(Mode mode = Mode::ZBuffer, float alpha = 1.0f) : mode_(mode), alpha_(alpha) {}
  std::string name() const override { return mode_ == Mode::ZBuffer ? "raster" : "blend"; }
  void run(FrameContext& frame) override;

 private:
  Mode mode_;
  float alpha_;
};

}  // namespace tlab::render
