#include "renderer/peel/depth_peeling.hpp"

#include <vector>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

namespace {
constexpr GLuint kBindAccumulator = 9;  // peel/peel_blend.comp

gpu::Texture makeTarget(GLenum format, int width, int height) {
  gpu::Texture t = gpu::makeTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format, width, height);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}
}  // namespace

DepthPeeling::DepthPeeling(gpu::ShaderCache& shaders, int width, int height, int maxIterations)
    : shaders_(shaders), width_(width), height_(height), maxIterations_(maxIterations) {
  color_ = makeTarget(GL_RGBA32F, width, height);
  normalDepth_ = makeTarget(GL_RGBA32F, width, height);
  for (int i = 0; i < 2; ++i) {
    depth_[i] = makeTarget(GL_DEPTH_COMPONENT32F, width, height);
    fbo_[i] = gpu::makeFramebuffer();
    glNamedFramebufferTexture(fbo_[i].id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    glNamedFramebufferTexture(fbo_[i].id(), GL_COLOR_ATTACHMENT1, normalDepth_.id(), 0);
    glNamedFramebufferTexture(fbo_[i].id(), GL_DEPTH_ATTACHMENT, depth_[i].id(), 0);
    const GLenum drawBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo_[i].id(), 2, drawBuffers);
    if (glCheckNamedFramebufferStatus(fbo_[i].id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw gpu::GlError("the depth-peeling framebuffer is incomplete");
  }
  query_ = gpu::makeQuery(GL_ANY_SAMPLES_PASSED);
  accum_ = gpu::Buffer(std::size_t(width) * height * sizeof(glm::vec4));
  gpu::checkGl("creating the depth peeler");
}

// Peel stage: renders the nearest layer behind layer − 1 into fbo_[layer % 2]; returns whether
// any fragment was rendered (the occlusion query of IRIS Sec. 5.1).
bool DepthPeeling::peel(const GpuScene& scene, const RasterUniforms& u, const IllustrativeSettings& settings, int layer) {
  const auto& program = shaders_.graphics("buffer/scene_geometry.vert", "peel/peel_layer.frag", settings.defines());
  const int current = layer % 2;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_[current].id());
  glViewport(0, 0, width_, height_);
  const float zero[4] = {0, 0, 0, 0};
  const float farDepth = 1.0f;
  glClearNamedFramebufferfv(fbo_[current].id(), GL_COLOR, 0, zero);
  glClearNamedFramebufferfv(fbo_[current].id(), GL_COLOR, 1, zero);
  glClearNamedFramebufferfv(fbo_[current].id(), GL_DEPTH, 0, &farDepth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  program.use();
  setCameraUniforms(program, u);
  glUniform1i(program.uniform("uLayer"), layer);
  glUniform1i(program.uniform("uPreviousDepth"), 0);
  glBindTextureUnit(0, depth_[1 - current].id());
  settings.setUniforms(program, width_, height_);
  scene.bindObjectTable();
  glBeginQuery(GL_ANY_SAMPLES_PASSED, query_.id());
  scene.draw();
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  glBindTextureUnit(0, 0);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  GLuint anySamples = 0;
  glGetQueryObjectuiv(query_.id(), GL_QUERY_RESULT, &anySamples);
  return anySamples != 0;
}

// Blend stage: silhouettes and under-blending of the layer just peeled.
void DepthPeeling::blend(const IllustrativeSettings& settings) {
  const auto& program = shaders_.compute("peel/peel_blend.comp", settings.defines());
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  program.use();
  glUniform1i(program.uniform("uWidth"), width_);
  glUniform1i(program.uniform("uHeight"), height_);
  settings.setUniforms(program, width_, height_);
  glBindTextureUnit(0, color_.id());
  glBindTextureUnit(1, normalDepth_.id());
  accum_.bindBase(GL_SHADER_STORAGE_BUFFER, kBindAccumulator);
  gpu::dispatchLinear(std::size_t(width_) * height_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindTextureUnit(0, 0);
  glBindTextureUnit(1, 0);
}

core::Image DepthPeeling::render(const GpuScene& scene, const RasterUniforms& uniforms, const IllustrativeSettings& settings,
                          glm::vec4 background, PassTimer& timer) {
  const std::size_t pixels = std::size_t(width_) * height_;
  const std::vector<glm::vec4> start(pixels, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // c = 0, T = 1
  accum_.upload(start.data(), start.size() * sizeof(glm::vec4));
  iterations_ = 0;
  for (int layer = 0; layer < maxIterations_; ++layer) {
    bool rendered = false;
    timer.time("peel", [&] { rendered = peel(scene, uniforms, settings, layer); });
    ++iterations_;
    if (!rendered) break;  // IRIS Sec. 5.1: iterations = layers + 1
    timer.time("blend", [&] { blend(settings); });
  }
  std::vector<glm::vec4> accum(pixels);
  accum_.download(accum.data(), accum.size() * sizeof(glm::vec4));
  core::Image image(width_, height_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const glm::vec4 a = accum[std::size_t(height_ - 1 - y) * width_ + x];
      image.at(x, y) = glm::vec4(glm::vec3(a) + a.w * glm::vec3(background), 1.0f);
    }
  gpu::checkGl("depth peeling");
  return image;
}

void DepthPeeling::build(FrameContext& frame, PassTimer& timer) {
  frame.image = render(frame.gpuScene, frame.raster, shading_, frame.background, timer);
}

}  // namespace tlab::render
