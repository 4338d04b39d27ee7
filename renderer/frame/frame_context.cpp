#include "renderer/frame/frame_context.hpp"

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"

#include <vector>

namespace tlab::render {

void readOutputBuffer(const gpu::Buffer& output, core::Image& image) {
  const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
  std::vector<glm::vec4> gl(w * h);
  output.download(gl.data(), gl.size() * sizeof(glm::vec4));
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) image.pixels[y * w + x] = gl[(h - 1 - y) * w + x];
}

void dispatchCompose(FrameContext& frame, const gpu::Buffer& output, std::size_t pixels, const char* shader, GLbitfield barrier) {
  gpu::dispatchLinear(pixels);
  glMemoryBarrier(barrier);
  readOutputBuffer(output, frame.image);
  gpu::checkGl(shader);
}

}  // namespace tlab::render
