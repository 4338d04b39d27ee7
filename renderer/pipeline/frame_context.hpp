#pragma once
// What every render pass of one frame sees: the scene on the GPU, the illustration buffer (when
// the style uses fragment lists), the style's parameters, and the image the frame produces.
#include <glm/glm.hpp>

#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/ops/group_draw_order.hpp"
#include "core/image.hpp"
#include "renderer/pipeline/gpu_scene.hpp"
#include "renderer/pipeline/pass_timer.hpp"
#include "renderer/scene/scene.hpp"
#include "renderer/styles/style_params.hpp"

namespace tlab::render {

class BucketedKBuffer;

struct FrameContext {
  const Scene& scene;
  const GpuScene& gpuScene;
  const RasterUniforms& raster;
  const Camera& camera;
  const StyleParams& params;
  int width;
  int height;
  glm::vec4 background;
  FragmentBuffer* buffer;  // null for styles without fragment lists
  core::Image& image;            // the frame's result, row 0 = top
  gpu::ShaderCache& shaders;
  GroupDrawOrder* drawOrder = nullptr;  // frame-coherent back-to-front group order (dynamic style)
  BucketedKBuffer* kbuffer = nullptr;  // the bucketed k-buffer, for styles that fill with it
};

// One pass of a style (VTK render-pass style): a small object with one job.
class RenderPass {
 public:
  virtual ~RenderPass() = default;
  virtual std::string name() const = 0;
  virtual void run(FrameContext& frame) = 0;
  // What the pass computes and what it leaves out for these parameters (for --stats-json).
  virtual std::vector<std::string> operations() const { return {}; }
};

// Reads an RGBA float SSBO of width*height texels in GL order (row 0 = bottom) into the image,
// flipping so that row 0 is the top.
void readOutputBuffer(const gpu::Buffer& output, core::Image& image);

}  // namespace tlab::render
