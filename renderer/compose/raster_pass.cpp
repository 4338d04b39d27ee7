#include "renderer/compose/raster_pass.hpp"

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/gpu/shader_program.hpp"

namespace tlab::render {

namespace {

// The float colour and depth targets and the pack buffer the colour is read through, kept by the
// renderer across frames (its scene cache) and re-made when the size changes. Made afresh each
// frame, with a frame-sized vector to read into and a flipping copy after, they cost an H200 63 ms
// of a 2048² frame (issue #29's GPU table).
struct RasterTarget {
  explicit RasterTarget(const Scene&) {}
  void fit(int w, int h) {
    if (w == width && h == height) return;
    color = gpu::makeRenderbuffer(), depth = gpu::makeRenderbuffer();
    glNamedRenderbufferStorage(color.id(), GL_RGBA32F, w, h);
    glNamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, w, h);
    fbo = gpu::makeFramebuffer();
    glNamedFramebufferRenderbuffer(fbo.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
    glNamedFramebufferRenderbuffer(fbo.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw gpu::GlError("the opaque colour/depth framebuffer is incomplete");
    pixels = gpu::Buffer(std::size_t(w) * std::size_t(h) * sizeof(glm::vec4));
    width = w, height = h;
  }
  int width = 0, height = 0;
  gpu::Renderbuffer color, depth;
  gpu::Framebuffer fbo;
  gpu::Buffer pixels;  // RGBA32F in GL order (row 0 = bottom), as a compositor's output
};

// Copies the footprint's pixels of the bound read framebuffer into `pixels` at their places in a
// width-wide image (the rest is left as it was: readOutputRect does not read it).
void packFootprint(const gpu::Buffer& pixels, int width, PixelRect rect) {
  if (rect.pixels() == 0) return;
  glBindBuffer(GL_PIXEL_PACK_BUFFER, pixels.id());
  glPixelStorei(GL_PACK_ROW_LENGTH, width);
  const std::size_t offset = (std::size_t(rect.y0) * std::size_t(width) + std::size_t(rect.x0)) * sizeof(glm::vec4);
  glReadPixels(rect.x0, rect.y0, rect.width(), rect.height(), GL_RGBA, GL_FLOAT, reinterpret_cast<void*>(offset));
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
}

}  // namespace

void rasterScene(FrameContext& frame, RasterMode mode, float alpha) {
  const int w = frame.width, h = frame.height;
  RasterTarget& target = frame.derived<RasterTarget>();
  target.fit(w, h);
  const auto& program =
      frame.shaders.graphics("buffer/scene_geometry.vert", "compose/raster.frag", withLighting({}, frame.raster.lighting));
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
  glViewport(0, 0, w, h);
  glDisable(GL_CULL_FACE);
  if (mode == RasterMode::ZBuffer) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
  } else {
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    // c ← α·c_src + (1 − α)·c_dst, in whatever order the triangles arrive.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  }
  const glm::vec4 clear(frame.background.r, frame.background.g, frame.background.b, 1.0f);
  glClearColor(clear.r, clear.g, clear.b, clear.a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  program.use();
  setCameraUniforms(program, frame.raster);
  glUniform1f(program.uniform("uAlpha"), mode == RasterMode::ZBuffer ? 1.0f : alpha);
  frame.gpuScene.bindObjectTable();
  frame.gpuScene.draw();
  // No fragment lands outside the scene's footprint, so the pixels there keep the clear colour.
  const PixelRect footprint = sceneFootprint(frame);
  packFootprint(target.pixels, w, footprint);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  readOutputRect(target.pixels, frame.image, footprint, clear);
  gpu::checkGl("rasterizing the scene");
}

}  // namespace tlab::render
