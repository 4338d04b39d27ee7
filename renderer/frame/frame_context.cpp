#include "renderer/frame/frame_context.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"

namespace tlab::render {

void readOutputBuffer(const gpu::Buffer& output, core::Image& image) {
  readOutputRect(output, image, PixelRect{0, 0, image.width, image.height}, glm::vec4(0.0f));
}

// One mapping of the rectangle's rows, copied row by row straight into the image (flipped), without
// a frame-sized copy in between: a fresh 16 bytes per pixel each frame costs page faults whose price
// varies with the machine's load. (One download per row, 512 of them at 512², cost more: issue #29.)
void readOutputRect(const gpu::Buffer& output, core::Image& image, PixelRect rect, glm::vec4 outside) {
  const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
  for (std::size_t y = 0; y < h; ++y) {
    glm::vec4* const row = &image.pixels[(h - 1 - y) * w];
    const bool inside = int(y) >= rect.y0 && int(y) < rect.y1;
    std::fill(row, row + (inside ? rect.x0 : w), outside);
    if (inside) std::fill(row + rect.x1, row + w, outside);
  }
  if (rect.pixels() == 0) return;
  const std::size_t rowBytes = w * sizeof(glm::vec4);
  const gpu::MappedRead rows(output, rect.height() * rowBytes, rect.y0 * rowBytes);
  const glm::vec4* const mapped = rows.as<glm::vec4>();
  for (int y = rect.y0; y < rect.y1; ++y)
    std::memcpy(&image.pixels[(h - 1 - y) * w + rect.x0], mapped + (y - rect.y0) * w + rect.x0, rect.width() * sizeof(glm::vec4));
}

PixelRect sceneFootprint(const FrameContext& frame) {
  const PixelRect whole{0, 0, frame.width, frame.height};
  const std::optional<BoundingBox>& box = frame.gpuScene.bounds();  // computed once, at upload
  if (!box) return PixelRect{};  // no vertex: no fragment
  const glm::vec3 lo = box->lo, hi = box->hi;
  // The box is convex and, when in front of the eye (w > 0) everywhere, so is its perspective
  // image: the corners' window positions bound every vertex's, hence every triangle's.
  const glm::mat4 clip = frame.raster.projection * frame.raster.view;
  glm::vec2 wlo(std::numeric_limits<float>::max()), whi(std::numeric_limits<float>::lowest());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z);
    const glm::vec4 c = clip * glm::vec4(p, 1.0f);
    if (!(c.w > 0.0f)) return whole;
    const glm::vec2 window = (glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(frame.width, frame.height);
    if (!std::isfinite(window.x) || !std::isfinite(window.y)) return whole;
    wlo = glm::min(wlo, window);
    whi = glm::max(whi, window);
  }
  // A pixel holds a fragment only when its centre (x + 0.5) lies in the triangle: x in
  // [floor(lo - 0.5), ceil(hi)); one more pixel each side for rounding.
  const auto clampTo = [](float v, int n) { return int(std::clamp(v, 0.0f, float(n))); };
  PixelRect r{clampTo(std::floor(wlo.x) - 1.0f, frame.width), clampTo(std::floor(wlo.y) - 1.0f, frame.height),
              clampTo(std::ceil(whi.x) + 1.0f, frame.width), clampTo(std::ceil(whi.y) + 1.0f, frame.height)};
  if (r.x0 >= r.x1 || r.y0 >= r.y1) return PixelRect{};
  return r;
}

void finishCompose(FrameContext& frame, const gpu::Buffer& output, const char* shader, GLbitfield barrier) {
  glMemoryBarrier(barrier);
  timePart(frame.timer, "compose read-back", [&] { readOutputBuffer(output, frame.image); });
  gpu::checkGl(shader);
}

void dispatchCompose(FrameContext& frame, const gpu::Buffer& output, std::size_t pixels, const char* shader, GLbitfield barrier) {
  gpu::dispatchLinear(pixels);
  finishCompose(frame, output, shader, barrier);
}

}  // namespace tlab::render
