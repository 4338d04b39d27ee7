#include "renderer/compose/blend_compositor.hpp"

#include <thread>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/compose/host_blend.hpp"

namespace tlab::render {

void blendColourPlaneOnHost(FrameContext& frame, const FragmentBuffer& buffer, PixelRect rect, float alpha,
                            const float* alphas, const float* betas, const float* gammas) {
  const std::size_t pixels = buffer.pixels();
  const gpu::MappedRead counts(buffer.pixelCountBuffer(), pixels * 4), heads(buffer.pixelHeadBuffer(), pixels * 4),
      plane(*buffer.colorPlane(), std::size_t(buffer.fragmentCount()) * 4);
  SortedColours in{counts.as<std::uint32_t>(), heads.as<std::uint32_t>(), plane.as<std::uint32_t>(), buffer.width(), buffer.height()};
  in.alpha = alphas;
  in.beta = betas;
  in.gamma = gammas;
  timePart(frame.timer, "compose blend on the host", [&] {
    blendOnHost(in, rect.x0, rect.y0, rect.x1, rect.y1, alpha, glm::vec3(frame.background), frame.image,
                std::thread::hardware_concurrency());
  });
}

// The lists sorted by the fill's sort pass, or, when the fill left them unsorted (FillSpec::
// sortsInCompose), sorted here as they are blended (compose/blend.comp, TLAB_FUSED), or, where
// the GL runs on the CPU, their colour words sorted by host code and blended here by host code. Only the
// pixels the scene can reach are composed and read back; the others are the background
// (c = 0, T = 1: c + T·c_background), painted here (issue #29: most of a 512² frame of the
// teapot is background).
void composeBlend(FrameContext& frame, float alpha) {
  FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  if (buffer.colorPlane() && buffer.sortsOnHost()) {  // the host sorted the colours: blend them there too
    blendColourPlaneOnHost(frame, buffer, sceneFootprint(frame), alpha);
    return;
  }
  gpu::ShaderDefines defines = buffer.layout().defines();
  if (!buffer.sorted()) {
    defines.emplace_back("TLAB_FUSED", "1");
    if (buffer.bindUnsorted()) defines.emplace_back("TLAB_SLOTS", "1");
    // The register network of 16 for frames whose slots hold lists longer than 8 (its keys hold
    // triangle * 16 + position in one word), the order buffer for lists beyond 4 otherwise.
    if (buffer.slotsUsed() > 8 && frame.gpuScene.triangleCount() <= (std::size_t{1} << 28))
      defines.emplace_back("TLAB_NETWORK_SORT", "1");
  } else {
    buffer.bindSorted();
  }
  const auto& program = frame.shaders.compute("compose/blend.comp", defines);
  const gpu::Buffer& output = buffer.composeOutput();
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 9);  // BIND_OUTPUT
  program.use();
  const PixelRect rect = sceneFootprint(frame);
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(buffer.pixels()));
  glUniform1i(program.uniform("uWidth"), buffer.width());
  glUniform4i(program.uniform("uRect"), rect.x0, rect.y0, rect.width(), rect.height());
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1f(program.uniform("uAlpha"), alpha);
  gpu::dispatchLinear(rect.pixels());
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  timePart(frame.timer, "compose read-back",
           [&] { readOutputRect(output, frame.image, rect, glm::vec4(glm::vec3(frame.background), 1.0f)); });
  gpu::checkGl("compose/blend.comp");
}

}  // namespace tlab::render
