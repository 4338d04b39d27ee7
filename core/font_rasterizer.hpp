#pragma once
// One TrueType font rasterized with stb_truetype: glyph coverage bitmaps and metrics at a pixel
// height. Shared by everything that writes text into pictures (stimulus labels, the study window).
#include <memory>
#include <string>
#include <vector>

namespace tlab::core {

struct GlyphBitmap {
  int width = 0, height = 0;  // coverage bitmap size
  int xoff = 0, yoff = 0;     // offset of its top-left corner from the pen position on the baseline
  float advance = 0.0f;       // pen advance in pixels
  std::vector<unsigned char> coverage;  // width * height, 0..255
};

// A DejaVu font file (Debian's fonts-dejavu-core): $TLAB_FONT_DIR/NAME when that variable is set
// (a relocatable bundle carries its fonts: scripts/bundle.sh), else /usr/share/fonts/truetype/dejavu/NAME.
std::string dejavuFontPath(const std::string& name);

class FontRasterizer {
 public:
  // Throws std::runtime_error naming the file when it cannot be read or parsed.
  explicit FontRasterizer(const std::string& fontPath);
  ~FontRasterizer();
  FontRasterizer(const FontRasterizer&) = delete;
  FontRasterizer& operator=(const FontRasterizer&) = delete;

  GlyphBitmap glyph(char32_t codepoint, float pixelHeight) const;
  float advance(char32_t codepoint, float pixelHeight) const;
  float ascent(float pixelHeight) const;  // baseline distance below the top of a line

 private:
  struct Font;
  std::unique_ptr<Font> font_;
};

}  // namespace tlab::core
