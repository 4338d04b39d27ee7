#include "stimuli/sets/label_painter.hpp"

#include "core/font_rasterizer.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>


namespace tlab::stimuli {

struct LabelPainter::Font {
  explicit Font(const std::string& path) : rasterizer(path) {}
  core::FontRasterizer rasterizer;
};

namespace {

// Source-over blending of `color` with coverage `alpha` into a pixel.
void blend(core::Image& image, int x, int y, glm::vec4 color, float alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || alpha <= 0.0f) return;
  glm::vec4& p = image.at(x, y);
  const float a = std::clamp(alpha * color.a, 0.0f, 1.0f);
  p = glm::vec4(glm::vec3(p) * (1.0f - a) + glm::vec3(color) * a, std::max(p.a, a));
}

// A filled disk (anti-aliased by coverage of the distance to the edge).
void fillDisk(core::Image& image, glm::dvec2 c, double radius, glm::vec4 color) {
  for (int y = int(std::floor(c.y - radius - 1)); y <= int(std::ceil(c.y + radius + 1)); ++y)
    for (int x = int(std::floor(c.x - radius - 1)); x <= int(std::ceil(c.x + radius + 1)); ++x) {
      const double d = glm::distance(glm::dvec2(x + 0.5, y + 0.5), c);
      blend(image, x, y, color, float(std::clamp(radius - d + 0.5, 0.0, 1.0)));
    }
}

void fillRect(core::Image& image, double x0, double y0, double x1, double y1, glm::vec4 color) {
  for (int y = int(std::floor(y0)); y < int(std::ceil(y1)); ++y)
    for (int x = int(std::floor(x0)); x < int(std::ceil(x1)); ++x) blend(image, x, y, color, 1.0f);
}

void fillSegment(core::Image& image, glm::dvec2 a, glm::dvec2 b, double width, glm::vec4 color) {
  const glm::dvec2 lo = glm::min(a, b) - width, hi = glm::max(a, b) + width;
  const glm::dvec2 ab = b - a;
  const double len2 = std::max(glm::dot(ab, ab), 1e-12);
  for (int y = int(lo.y); y <= int(hi.y); ++y)
    for (int x = int(lo.x); x <= int(hi.x); ++x) {
      const glm::dvec2 p(x + 0.5, y + 0.5);
      const double t = std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0);
      const double d = glm::distance(p, a + t * ab);
      blend(image, x, y, color, float(std::clamp(0.5 * width - d + 0.5, 0.0, 1.0)));
    }
}

}  // namespace

std::string LabelPainter::defaultFontPath() { return core::dejavuFontPath("DejaVuSans-Bold.ttf"); }

LabelPainter::LabelPainter(const std::string& fontPath) : font_(std::make_unique<Font>(fontPath)) {}

LabelPainter::~LabelPainter() = default;

double LabelPainter::textWidth(const std::string& text, double pixelHeight) const {
  double width = 0.0;
  for (const char ch : text) width += font_->rasterizer.advance(char32_t(static_cast<unsigned char>(ch)), float(pixelHeight));
  return width;
}

void LabelPainter::drawText(core::Image& image, double x, double y, const std::string& text, double pixelHeight, glm::vec4 color) const {
  const core::FontRasterizer& font = font_->rasterizer;
  const int baseline = int(std::lround(y + font.ascent(float(pixelHeight))));
  double penX = x;
  for (const char ch : text) {
    const core::GlyphBitmap g = font.glyph(char32_t(static_cast<unsigned char>(ch)), float(pixelHeight));
    const int left = int(std::lround(penX)) + g.xoff;
    for (int row = 0; row < g.height; ++row)
      for (int col = 0; col < g.width; ++col)
        blend(image, left + col, baseline + g.yoff + row, color, float(g.coverage[std::size_t(row) * g.width + col]) / 255.0f);
    penX += g.advance;
  }
}

core::Image LabelPainter::drawMarks(const core::Image& picture, const std::vector<ProbeMark>& marks) {
  core::Image marked = picture;
  paint(marked, marks);
  return marked;
}

void LabelPainter::paint(core::Image& image, const std::vector<ProbeMark>& marks) const {
  const double unit = std::max(12.0, image.height / 40.0);  // letter height
  const glm::vec4 dark(0.05f, 0.05f, 0.05f, 1.0f), white(1.0f), accent(1.0f, 0.85f, 0.0f, 1.0f);
  for (const auto& m : marks) {
    // The point: a dark ring with a bright centre, exactly at the probe position.
    fillDisk(image, m.pixel, 0.32 * unit, dark);
    fillDisk(image, m.pixel, 0.18 * unit, accent);
    // The label box, up and to the right, with a leader line.
    const double w = textWidth(m.label, unit) + 0.5 * unit, h = 1.25 * unit;
    double bx = m.pixel.x + 0.7 * unit, by = m.pixel.y - 0.7 * unit - h;
    if (bx + w > image.width) bx = m.pixel.x - 0.7 * unit - w;
    if (by < 0) by = m.pixel.y + 0.7 * unit;
    const glm::dvec2 corner(bx < m.pixel.x ? bx + w : bx, by < m.pixel.y ? by + h : by);
    fillSegment(image, m.pixel, corner, 0.12 * unit, dark);
    fillRect(image, bx - 0.1 * unit, by - 0.1 * unit, bx + w + 0.1 * unit, by + h + 0.1 * unit, dark);
    fillRect(image, bx, by, bx + w, by + h, white);
    drawText(image, bx + 0.25 * unit, by + 0.05 * unit, m.label, unit, dark);
  }
}

}  // namespace tlab::stimuli
