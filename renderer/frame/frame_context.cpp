#include "renderer/frame/frame_context.hpp"

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"

namespace tlab::render {

// Row by row straight into the image (flipped), without a frame-sized copy in between: a fresh
// 16 bytes per pixel each frame costs page faults whose price varies with the machine's load.
void readOutputBuffer(const gpu::Buffer& output, core::Image& image) {
  const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
  const std::size_t rowBytes = w * sizeof(glm::vec4);
  for (std::size_t y = 0; y < h; ++y) output.download(&image.pixels[(h - 1 - y) * w], rowBytes, y * rowBytes);
}

void dispatchCompose(FrameContext& frame, const gpu::Buffer& output, std::size_t pixels, const char* shader, GLbitfield barrier) {
  gpu::dispatchLinear(pixels);
  glMemoryBarrier(barrier);
  readOutputBuffer(output, frame.image);
  gpu::checkGl(shader);
}

}  // namespace tlab::render
