#pragma once
// TextPainter: draws UTF-8 text into a Canvas with stb_truetype and one TrueType font (DejaVu Sans
// by default), anti-aliased, with word wrapping. Glyph bitmaps are cached per (codepoint, size).
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "study/run/canvas.hpp"

namespace tlab::study {

// DejaVu Sans, from $TLAB_FONT_DIR when set (core/font_rasterizer.hpp).
std::string defaultFont();

class TextPainter {
 public:
  // Throws std::runtime_error naming the font file when it cannot be read or parsed.
  explicit TextPainter(const std::string& fontPath = defaultFont());
  ~TextPainter();
  TextPainter(const TextPainter&) = delete;
  TextPainter& operator=(const TextPainter&) = delete;

  // Draws one line with its top-left corner at (x, y); returns the width drawn.
  int drawLine(Canvas& canvas, std::string_view text, int x, int y, float pixelHeight, Rgba color);
  int lineWidth(std::string_view text, float pixelHeight);
  // The lines `text` word-wraps into at `width` (its own newlines kept; a word wider than `width`
  // stays whole on its own line).
  std::vector<std::string> wrapLines(std::string_view text, int width, float pixelHeight);
  // Word-wraps into `width`; returns the height used.
  int drawParagraph(Canvas& canvas, std::string_view text, int x, int y, int width, float pixelHeight, Rgba color);
  int lineHeight(float pixelHeight) const;

 private:
  struct Glyph {
    int width = 0, height = 0, xoff = 0, yoff = 0, advance = 0;
    std::vector<unsigned char> bitmap;
  };
  const Glyph& glyph(char32_t codepoint, float pixelHeight);

  struct FontInfo;
  FontInfo* font_;
  std::map<std::pair<char32_t, int>, Glyph> cache_;
};

// Splits UTF-8 into code points; invalid bytes become U+FFFD.
std::u32string decodeUtf8(std::string_view text);

}  // namespace tlab::study
