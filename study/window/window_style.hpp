#pragma once
// The participant window's colours and its button, shared by the trial screen and the screens
// around it (window_responder.cpp, window_screens.cpp).
#include <algorithm>
#include <string>

#include "study/run/canvas.hpp"
#include "study/window/screen_layout.hpp"
#include "study/run/text_painter.hpp"

namespace tlab::study {

constexpr Rgba kInk{20, 20, 20, 255};
constexpr Rgba kMuted{110, 110, 110, 255};
constexpr Rgba kPaper{245, 245, 242, 255};
constexpr Rgba kBand{228, 228, 224, 255};
constexpr Rgba kAccent{30, 90, 200, 255};
constexpr Rgba kWarn{190, 30, 30, 255};
constexpr Rgba kRight{20, 140, 60, 255};

// Typed text: one code point appended as UTF-8, the last code point removed (Backspace).
inline std::string utf8(char32_t c) {
  std::string s;
  if (c < 0x80) s += char(c);
  else if (c < 0x800) s += {char(0xC0 | (c >> 6)), char(0x80 | (c & 0x3F))};
  else if (c < 0x10000) s += {char(0xE0 | (c >> 12)), char(0x80 | ((c >> 6) & 0x3F)), char(0x80 | (c & 0x3F))};
  else s += {char(0xF0 | (c >> 18)), char(0x80 | ((c >> 12) & 0x3F)), char(0x80 | ((c >> 6) & 0x3F)), char(0x80 | (c & 0x3F))};
  return s;
}

inline void dropLastCodepoint(std::string& s) {
  while (!s.empty() && (static_cast<unsigned char>(s.back()) & 0xC0) == 0x80) s.pop_back();
  if (!s.empty()) s.pop_back();
}

inline void drawButton(Canvas& c, TextPainter& p, const Button& b, bool selected) {
  c.fillRect(b.rect, selected ? kAccent : Rgba{255, 255, 255, 255});
  c.strokeRect(b.rect, kInk, 2);
  const float size = float(b.rect.height) * 0.5f;
  const int w = p.lineWidth(b.label, size);
  p.drawLine(c, b.label, b.rect.x + std::max(8, (b.rect.width - w) / 2), b.rect.y + (b.rect.height - p.lineHeight(size)) / 2 + 2, size,
             selected ? Rgba{255, 255, 255, 255} : kInk);
}

}  // namespace tlab::study
