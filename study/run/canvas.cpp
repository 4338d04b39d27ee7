#include "study/run/canvas.hpp"

#include <algorithm>
#include <cmath>

namespace tlab::study {

Canvas::Canvas(int width, int height, Rgba fill) : width_(width), height_(height), rgba_(std::size_t(width) * height * 4) {
  this->fill(fill);
}

Canvas::Canvas(const core::Image& image) : Canvas(image.width, image.height) {
  rgba_ = core::toRgba8(image);
}

void Canvas::fill(Rgba color) { fillRect({0, 0, width_, height_}, color); }

void Canvas::fillRect(const Rect& rect, Rgba color) {
  const int x0 = std::max(rect.x, 0), y0 = std::max(rect.y, 0);
  const int x1 = std::min(rect.x + rect.width, width_), y1 = std::min(rect.y + rect.height, height_);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) blend(x, y, color, 255);
}

void Canvas::strokeRect(const Rect& r, Rgba color, int t) {
  fillRect({r.x, r.y, r.width, t}, color);
  fillRect({r.x, r.y + r.height - t, r.width, t}, color);
  fillRect({r.x, r.y, t, r.height}, color);
  fillRect({r.x + r.width - t, r.y, t, r.height}, color);
}

void Canvas::blend(int x, int y, Rgba c, int coverage) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_ || coverage <= 0) return;
  const int a = coverage * c.a / 255;
  std::uint8_t* p = &rgba_[(std::size_t(y) * width_ + x) * 4];
  p[0] = std::uint8_t((c.r * a + p[0] * (255 - a)) / 255);
  p[1] = std::uint8_t((c.g * a + p[1] * (255 - a)) / 255);
  p[2] = std::uint8_t((c.b * a + p[2] * (255 - a)) / 255);
  p[3] = 255;
}

void Canvas::fillCircle(double cx, double cy, double radius, Rgba color) {
  for (int y = int(std::floor(cy - radius - 1)); y <= int(std::ceil(cy + radius + 1)); ++y)
    for (int x = int(std::floor(cx - radius - 1)); x <= int(std::ceil(cx + radius + 1)); ++x) {
      const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      blend(x, y, color, int(255 * std::clamp(radius + 0.5 - d, 0.0, 1.0)));
    }
}

void Canvas::strokeCircle(double cx, double cy, double radius, double thickness, Rgba color) {
  const double outer = radius + thickness / 2;
  for (int y = int(std::floor(cy - outer - 1)); y <= int(std::ceil(cy + outer + 1)); ++y)
    for (int x = int(std::floor(cx - outer - 1)); x <= int(std::ceil(cx + outer + 1)); ++x) {
      const double d = std::abs(std::hypot(x + 0.5 - cx, y + 0.5 - cy) - radius);
      blend(x, y, color, int(255 * std::clamp(thickness / 2 + 0.5 - d, 0.0, 1.0)));
    }
}

void Canvas::drawCanvas(const Canvas& source, const Rect& target) {
  for (int y = std::max(target.y, 0); y < std::min(target.y + target.height, height_); ++y) {
    const int sy = std::min(source.height_ - 1, (y - target.y) * source.height_ / std::max(target.height, 1));
    for (int x = std::max(target.x, 0); x < std::min(target.x + target.width, width_); ++x) {
      const int sx = std::min(source.width_ - 1, (x - target.x) * source.width_ / std::max(target.width, 1));
      const std::uint8_t* s = &source.rgba_[(std::size_t(sy) * source.width_ + sx) * 4];
      std::uint8_t* d = &rgba_[(std::size_t(y) * width_ + x) * 4];
      std::copy(s, s + 4, d);
    }
  }
}

core::Image Canvas::toImage() const {
  core::Image image(width_, height_);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = glm::vec4(rgba_[4 * i], rgba_[4 * i + 1], rgba_[4 * i + 2], rgba_[4 * i + 3]) / 255.0f;
  return image;
}

}  // namespace tlab::study
