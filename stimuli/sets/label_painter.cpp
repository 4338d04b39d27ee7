#include "stimuli/sets/label_painter.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

// stb_truetype's implementation lives in this file only (static: no clash with other users).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb_truetype.h>
#pragma GCC diagnostic pop

namespace tlab::stimuli {

struct LabelPainter::Font {
  std::vector<unsigned char> bytes;
  stbtt_fontinfo info{};
};

namespace {

// Source-over blending of `color` with coverage `alpha` into a pixel.
void blend(render::Image& image, int x, int y, glm::vec4 color, float alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || alpha <= 0.0f) return;
  glm::vec4& p = image.at(x, y);
  const float a = std::clamp(alpha * color.a, 0.0f, 1.0f);
  p = glm::vec4(glm::vec3(p) * (1.0f - a) + glm::vec3(color) * a, std::max(p.a, a));
}

// A filled disk (anti-aliased by coverage of the distance to the edge).
void fillDisk(render::Image& image, glm::dvec2 c, double radius, glm::vec4 color) {
  for (int y = int(std::floor(c.y - radius - 1)); y <= int(std::ceil(c.y + radius + 1)); ++y)
    for (int x = int(std::floor(c.x - radius - 1)); x <= int(std::ceil(c.x + radius + 1)); ++x) {
      const double d = glm::distance(glm::dvec2(x + 0.5, y + 0.5), c);
      blend(image, x, y, color, float(std::clamp(radius - d + 0.5, 0.0, 1.0)));
    }
}

void fillRect(render::Image& image, double x0, double y0, double x1, double y1, glm::vec4 color) {
  for (int y = int(std::floor(y0)); y < int(std::ceil(y1)); ++y)
    for (int x = int(std::floor(x0)); x < int(std::ceil(x1)); ++x) blend(image, x, y, color, 1.0f);
}

void fillSegment(render::Image& image, glm::dvec2 a, glm::dvec2 b, double width, glm::vec4 color) {
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

std::string LabelPainter::defaultFontPath() {
#ifdef TLAB_LABEL_FONT
  return TLAB_LABEL_FONT;
#else
  return "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";
#endif
}

LabelPainter::LabelPainter(const std::string& fontPath) : font_(std::make_unique<Font>()) {
  std::ifstream in(fontPath, std::ios::binary);
  font_->bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw std::runtime_error(fontPath + ": cannot read the label font");
  if (font_->bytes.empty() || !stbtt_InitFont(&font_->info, font_->bytes.data(), stbtt_GetFontOffsetForIndex(font_->bytes.data(), 0)))
    throw std::runtime_error(fontPath + ": cannot load the label font (install fonts-dejavu-core)");
}

LabelPainter::~LabelPainter() = default;

double LabelPainter::textWidth(const std::string& text, double pixelHeight) const {
  const float scale = stbtt_ScaleForPixelHeight(&font_->info, float(pixelHeight));
  double width = 0.0;
  for (const char ch : text) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font_->info, ch, &advance, &bearing);
    width += advance * scale;
  }
  return width;
}

void LabelPainter::drawText(render::Image& image, double x, double y, const std::string& text, double pixelHeight, glm::vec4 color) const {
  const float scale = stbtt_ScaleForPixelHeight(&font_->info, float(pixelHeight));
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&font_->info, &ascent, &descent, &gap);
  const int baseline = int(std::lround(y + ascent * scale));
  double penX = x;
  for (const char ch : text) {
    int w = 0, h = 0, xoff = 0, yoff = 0;
    unsigned char* bitmap = stbtt_GetCodepointBitmap(&font_->info, scale, scale, ch, &w, &h, &xoff, &yoff);
    const int left = int(std::lround(penX)) + xoff;
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col) blend(image, left + col, baseline + yoff + row, color, float(bitmap[row * w + col]) / 255.0f);
    stbtt_FreeBitmap(bitmap, nullptr);
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font_->info, ch, &advance, &bearing);
    penX += advance * scale;
  }
}

void LabelPainter::paint(render::Image& image, const std::vector<ProbeMark>& marks) const {
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
