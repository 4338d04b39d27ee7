#include "core/font_rasterizer.hpp"

#include <cstdlib>
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

namespace tlab::core {

std::string dejavuFontPath(const std::string& name) {
  const char* dir = std::getenv("TLAB_FONT_DIR");
  return (dir && *dir ? std::string(dir) : std::string("/usr/share/fonts/truetype/dejavu")) + "/" + name;
}

struct FontRasterizer::Font {
  std::vector<unsigned char> bytes;
  stbtt_fontinfo info{};
};

FontRasterizer::FontRasterizer(const std::string& fontPath) : font_(std::make_unique<Font>()) {
  std::ifstream in(fontPath, std::ios::binary);
  font_->bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (font_->bytes.empty() ||
      !stbtt_InitFont(&font_->info, font_->bytes.data(), stbtt_GetFontOffsetForIndex(font_->bytes.data(), 0)))
    throw std::runtime_error(fontPath + ": cannot read the font (install fonts-dejavu-core)");
}

FontRasterizer::~FontRasterizer() = default;

float FontRasterizer::advance(char32_t codepoint, float pixelHeight) const {
  int advance = 0, bearing = 0;
  stbtt_GetCodepointHMetrics(&font_->info, int(codepoint), &advance, &bearing);
  return float(advance) * stbtt_ScaleForPixelHeight(&font_->info, pixelHeight);
}

float FontRasterizer::ascent(float pixelHeight) const {
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&font_->info, &ascent, &descent, &gap);
  return float(ascent) * stbtt_ScaleForPixelHeight(&font_->info, pixelHeight);
}

GlyphBitmap FontRasterizer::glyph(char32_t codepoint, float pixelHeight) const {
  GlyphBitmap g;
  const float scale = stbtt_ScaleForPixelHeight(&font_->info, pixelHeight);
  g.advance = advance(codepoint, pixelHeight);
  unsigned char* bitmap =
      stbtt_GetCodepointBitmap(&font_->info, scale, scale, int(codepoint), &g.width, &g.height, &g.xoff, &g.yoff);
  if (bitmap) {
    g.coverage.assign(bitmap, bitmap + std::size_t(g.width) * std::size_t(g.height));
    stbtt_FreeBitmap(bitmap, nullptr);
  }
  return g;
}

}  // namespace tlab::core
