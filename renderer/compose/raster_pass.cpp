#include "renderer/compose/raster_pass.hpp"

#include <vector>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/shader_program.hpp"

namespace tlab::render {

void rasterScene(FrameContext& frame, RasterMode mode, float alpha) {
  const int w = frame.width, h = frame.height;
  gpu::Renderbuffer color = gpu::makeRenderbuffer(), depth = gpu::makeRenderbuffer();
  glNamedRenderbufferStorage(color.id(), GL_RGBA32F, w, h);
  glNamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, w, h);
  gpu::Framebuffer fbo = gpu::makeFramebuffer();
  glNamedFramebufferRenderbuffer(fbo.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
  glNamedFramebufferRenderbuffer(fbo.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw gpu::GlError("the opaque colour/depth framebuffer is incomplete");
  const auto& program =
      frame.shaders.graphics("buffer/scene_geometry.vert", "compose/raster.frag", withLighting({}, frame.raster.lighting));
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
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
  glClearColor(frame.background.r, frame.background.g, frame.background.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  program.use();
  setCameraUniforms(program, frame.raster);
  glUniform1f(program.uniform("uAlpha"), mode == RasterMode::ZBuffer ? 1.0f : alpha);
  frame.gpuScene.bindObjectTable();
  frame.gpuScene.draw();
  std::vector<glm::vec4> gl(std::size_t(w) * h);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, gl.data());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) frame.image.at(x, y) = gl[std::size_t(h - 1 - y) * w + x];
  gpu::checkGl("rasterizing the scene");
}

}  // namespace tlab::render
