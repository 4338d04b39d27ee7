#pragma once
// Depth peeling (IRIS Sec. 5.1; Everitt 2001, Bavoil and Myers 2008): the scene is rasterized
// once per depth layer, front to back. Each iteration has a peel stage (the nearest fragment
// behind the previous layer, fully shaded: peel/peel_layer.frag) and a blend stage (Sobel
// silhouettes and under-blending into a float accumulator: peel/peel_blend.comp). An occlusion
// query ends the loop at the first iteration that renders nothing, so a frame takes exactly
// layers + 1 iterations. One of the three fills (pipeline/fill.hpp), a sibling of FragmentBuffer:
// the peer the illustration buffer is measured against (`tlab bench peel`). It composes the
// picture itself, with the local shading of the style (setShading).
#include <glm/glm.hpp>

#include "renderer/frame/raster_uniforms.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/gpu/shader_cache.hpp"
#include "core/image.hpp"
#include "renderer/frame/fill.hpp"
#include "renderer/frame/gpu_scene.hpp"
#include "renderer/frame/pass_timer.hpp"
#include "renderer/params/illustrative_settings.hpp"

namespace tlab::render {

class DepthPeeling final : public Fill {
 public:
  // `maxIterations` bounds the loop (a safety net; the occlusion query ends it first).
  DepthPeeling(gpu::ShaderCache& shaders, int width, int height, int maxIterations = 4096);

  // The local shading the next build() peels and blends with.
  void setShading(const IllustrativeSettings& settings) { shading_ = settings; }
  // Fill: render() into the frame's image with the frame's scene, camera and background.
  void build(FrameContext& frame, PassTimer& timer) override;
  bool composesPicture() const override { return true; }

  // Peels and blends every layer; returns the picture (row 0 = top). Timed as "peel" and "blend".
  core::Image render(const GpuScene& scene, const RasterUniforms& uniforms, const IllustrativeSettings& settings,
               glm::vec4 background, PassTimer& timer);

  int width() const { return width_; }
  int height() const { return height_; }
  // Of the last render(): loop iterations (layers + 1) and depth layers found.
  int iterations() const { return iterations_; }
  int layers() const { return iterations_ - 1; }

 private:
  bool peel(const GpuScene& scene, const RasterUniforms& uniforms, const IllustrativeSettings& settings, int layer);
  void blend(const IllustrativeSettings& settings);

  gpu::ShaderCache& shaders_;
  int width_, height_;
  int maxIterations_;
  int iterations_ = 0;
  IllustrativeSettings shading_;
  gpu::Texture depth_[2];  // ping-pong: this layer's depth, the previous layer's depth
  gpu::Texture color_, normalDepth_;
  gpu::Framebuffer fbo_[2];
  gpu::Query query_;
  gpu::Buffer accum_;
};

}  // namespace tlab::render
