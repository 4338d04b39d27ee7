#include "study/run/text_painter.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/font_rasterizer.hpp"

namespace tlab::study {

struct TextPainter::FontInfo {
  explicit FontInfo(const std::string& path) : rasterizer(path) {}
  core::FontRasterizer rasterizer;
};

std::u32string decodeUtf8(std::string_view text) {
  std::u32string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    bool ok = extra >= 0 && i + std::size_t(extra) < text.size();
    char32_t cp = ok ? char32_t(extra == 0 ? c : c & (0x3F >> extra)) : 0;
    for (int k = 1; ok && k <= extra; ++k) {
      const unsigned char cc = static_cast<unsigned char>(text[i + std::size_t(k)]);
      ok = (cc >> 6) == 2;
      cp = (cp << 6) | (cc & 0x3F);
    }
    out.push_back(ok ? cp : char32_t(0xFFFD));
    i += ok ? std::size_t(extra) + 1 : 1;
  }
  return out;
}

std::string defaultFont() { return core::dejavuFontPath("DejaVuSans.ttf"); }

TextPainter::TextPainter(const std::string& fontPath) : font_(new FontInfo(fontPath)) {}

TextPainter::~TextPainter() { delete font_; }

const TextPainter::Glyph& TextPainter::glyph(char32_t codepoint, float pixelHeight) {
  const auto key = std::make_pair(codepoint, int(pixelHeight * 4));
  const auto found = cache_.find(key);
  if (found != cache_.end()) return found->second;
  core::GlyphBitmap b = font_->rasterizer.glyph(codepoint, pixelHeight);
  Glyph g;
  g.width = b.width;
  g.height = b.height;
  g.xoff = b.xoff;
  g.yoff = b.yoff;
  g.advance = int(std::lround(b.advance));
  g.bitmap = std::move(b.coverage);
  return cache_.emplace(key, std::move(g)).first->second;
}

int TextPainter::lineHeight(float pixelHeight) const { return int(std::ceil(pixelHeight * 1.3f)); }

int TextPainter::lineWidth(std::string_view text, float pixelHeight) {
  int w = 0;
  for (const char32_t cp : decodeUtf8(text)) w += glyph(cp, pixelHeight).advance;
  return w;
}

int TextPainter::drawLine(Canvas& canvas, std::string_view text, int x, int y, float pixelHeight, Rgba color) {
  const int baseline = y + int(std::lround(font_->rasterizer.ascent(pixelHeight)));
  int pen = x;
  for (const char32_t cp : decodeUtf8(text)) {
    const Glyph& g = glyph(cp, pixelHeight);
    for (int gy = 0; gy < g.height; ++gy)
      for (int gx = 0; gx < g.width; ++gx)
        canvas.blend(pen + g.xoff + gx, baseline + g.yoff + gy, color, g.bitmap[std::size_t(gy) * g.width + gx]);
    pen += g.advance;
  }
  return pen - x;
}

std::vector<std::string> TextPainter::wrapLines(std::string_view text, int width, float pixelHeight) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t newline = text.find('\n', start);
    const std::string_view para = text.substr(start, newline == std::string_view::npos ? std::string_view::npos : newline - start);
    std::string line;
    std::size_t p = 0;
    while (p <= para.size()) {
      const std::size_t space = para.find(' ', p);
      const std::string_view word = para.substr(p, space == std::string_view::npos ? std::string_view::npos : space - p);
      const std::string candidate = line.empty() ? std::string(word) : line + " " + std::string(word);
      if (!line.empty() && lineWidth(candidate, pixelHeight) > width) {
        lines.push_back(line);
        line = std::string(word);
      } else {
        line = candidate;
      }
      if (space == std::string_view::npos) break;
      p = space + 1;
    }
    lines.push_back(line);
    if (newline == std::string_view::npos) break;
    start = newline + 1;
  }
  return lines;
}

int TextPainter::drawParagraph(Canvas& canvas, std::string_view text, int x, int y, int width, float pixelHeight, Rgba color) {
  int cy = y;
  for (const auto& line : wrapLines(text, width, pixelHeight)) {
    drawLine(canvas, line, x, cy, pixelHeight, color);
    cy += lineHeight(pixelHeight);
  }
  return cy - y;
}

}  // namespace tlab::study
