#pragma once
// Canvas: an RGBA8 picture (row 0 = top) the study screens and stimulus marks are drawn into,
// then shown with WindowContext::present or encoded as PNG. Text uses TextPainter.
#include <cstdint>
#include <vector>

#include "core/image.hpp"

namespace tlab::study {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
  bool contains(double px, double py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

class Canvas {
 public:
  Canvas(int width, int height, Rgba fill = {255, 255, 255, 255});
  explicit Canvas(const core::Image& image);  // 8-bit copy of a rendered image

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<std::uint8_t>& rgba() const { return rgba_; }

  void fill(Rgba color);
  void fillRect(const Rect& rect, Rgba color);
  void strokeRect(const Rect& rect, Rgba color, int thickness = 1);
  // Anti-aliased disc / ring centred at (cx, cy) in continuous pixel coordinates.
  void fillCircle(double cx, double cy, double radius, Rgba color);
  void strokeCircle(double cx, double cy, double radius, double thickness, Rgba color);
  // Alpha-blends `coverage` (0..255) of `color` into pixel (x, y); ignores points outside.
  void blend(int x, int y, Rgba color, int coverage);
  // Copies `source` scaled (nearest) into `target`.
  void drawCanvas(const Canvas& source, const Rect& target);

  core::Image toImage() const;

 private:
  int width_, height_;
  std::vector<std::uint8_t> rgba_;
};

}  // namespace tlab::study
