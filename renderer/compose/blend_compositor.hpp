#pragma once
#include "renderer/gpu/shader_program.hpp"
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

// Front-to-back alpha blending of the sorted lists with one opacity for every fragment
// (compose/blend.comp).
class BlendCompositor final : public RenderPass {
 public:
  explicit BlendCompositor(float alpha) : alpha_(alpha) {}
  std::string name() const override { return "compose"; }
  void run(FrameContext& frame) override;

 private:
  float alpha_;
};

}  // namespace tlab::render
