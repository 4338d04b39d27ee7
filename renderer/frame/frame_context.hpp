#pragma once
// What every render pass of one frame sees: the scene on the GPU, the fill the style declared
// (when it declared one), the style's parameters, and the image the frame produces.
#include <stdexcept>

#include <glm/glm.hpp>

#include "core/image.hpp"
#include "renderer/frame/fill.hpp"
#include "renderer/frame/gpu_scene.hpp"
#include "renderer/frame/pass_timer.hpp"
#include "renderer/frame/raster_uniforms.hpp"
#include "renderer/frame/scene_cache.hpp"
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/params/style_params.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::render {

class GroupDrawOrder;  // ops/group_draw_order.hpp, for the one style that keeps it across frames
class TransparencyFields;  // ops/transparency_fields.hpp, smart transparency's per-fragment fields

struct FrameContext {
  const Scene& scene;
  const GpuScene& gpuScene;
  const RasterUniforms& raster;
  const Camera& camera;
  const StyleParams& params;
  int width;
  int height;
  glm::vec4 background;
  Fill* fill;          // the fill the style declared; null for styles without one
  core::Image& image;  // the frame's result, row 0 = top
  gpu::ShaderCache& shaders;
  GroupDrawOrder* drawOrder = nullptr;  // frame-coherent back-to-front group order (dynamic style)
  TransparencyFields* fields = nullptr;  // per-fragment fields whose memory is kept across frames (smart style)
  SceneCache* sceneCache = nullptr;      // what styles derive from the scene alone, kept across frames
  PassTimer* timer = nullptr;            // the frame's pass timer, for passes that time their parts

  // The fill as the type a pass needs (a style's passes know which fill the style declared).
  template <typename T>
  T& fillAs() const {
    T* const typed = dynamic_cast<T*>(fill);
    if (!typed) throw std::logic_error("a render pass ran on a fill its style did not declare");
    return *typed;
  }
  // What a style derives from the scene alone (T(scene)), or keeps beside it, kept by the renderer
  // across frames (frame/scene_cache.hpp).
  template <typename T>
  T& derived() const {
    if (!sceneCache) throw std::logic_error("a render pass needs the renderer's scene cache");
    return sceneCache->get<T>(scene);
  }
};

// Reads an RGBA float SSBO of width*height texels in GL order (row 0 = bottom) into the image,
// flipping so that row 0 is the top.
void readOutputBuffer(const gpu::Buffer& output, core::Image& image);

// Pixels [x0, x1) x [y0, y1) in GL order (row 0 = bottom).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  std::size_t pixels() const { return std::size_t(width()) * std::size_t(height()); }
};
// Every pixel a fragment of the frame's scene can land on, and maybe more: the window
// rectangle of the scene's bounding box seen through the frame's camera, a pixel wider on each
// side; the whole image when the box reaches behind the eye. Pixels outside it have no fragment.
PixelRect sceneFootprint(const FrameContext& frame);
// readOutputBuffer for the texels inside `rect` only; the image's other pixels become `outside`.
void readOutputRect(const gpu::Buffer& output, core::Image& image, PixelRect rect, glm::vec4 outside);

// The end of every compositor, after its compute program (bound, uniforms set) was dispatched: a
// barrier, the output read into frame.image, and a GL error check naming `shader`.
void finishCompose(FrameContext& frame, const gpu::Buffer& output, const char* shader,
                   GLbitfield barrier = GL_BUFFER_UPDATE_BARRIER_BIT);
// The same, dispatching the program once per pixel first.
void dispatchCompose(FrameContext& frame, const gpu::Buffer& output, std::size_t pixels, const char* shader,
                     GLbitfield barrier = GL_BUFFER_UPDATE_BARRIER_BIT);

}  // namespace tlab::render
