// Probe labels: letters from a real font, markers at the probe position; SHA-256 of known inputs.
#include <gtest/gtest.h>

#include "stimuli/sets/label_painter.hpp"

namespace tlab::stimuli {
namespace {

std::size_t darkPixels(const core::Image& image, int x0, int y0, int x1, int y1) {
  std::size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) n += image.at(x, y).r < 0.3f ? 1 : 0;
  return n;
}

TEST(LabelPainter, DrawsAMarkerAtTheProbeAndItsLetterNextToIt) {
  const LabelPainter painter;
  core::Image image(200, 200, glm::vec4(1.0f));
  painter.paint(image, {{"A", "probe", glm::dvec3(0.0), glm::dvec2(100.0, 120.0)}});
  EXPECT_GT(darkPixels(image, 95, 115, 105, 125), 10u);  // the ring around the point
  EXPECT_GT(darkPixels(image, 100, 80, 140, 118), 30u);  // the boxed letter, up and to the right
  EXPECT_EQ(darkPixels(image, 0, 0, 60, 60), 0u);
}

TEST(LabelPainter, DifferentLettersHaveDifferentGlyphs) {
  const LabelPainter painter;
  core::Image a(60, 40, glm::vec4(1.0f)), x(60, 40, glm::vec4(1.0f));
  painter.drawText(a, 5, 5, "A", 24, glm::vec4(0, 0, 0, 1));
  painter.drawText(x, 5, 5, "X", 24, glm::vec4(0, 0, 0, 1));
  EXPECT_GT(darkPixels(a, 0, 0, 60, 40), 20u);
  EXPECT_NE(a.pixels, x.pixels);
  EXPECT_GT(painter.textWidth("AB", 24), painter.textWidth("A", 24));
}

TEST(LabelPainter, AMissingFontIsAClearError) {
  EXPECT_THROW(LabelPainter("/no/such/font.ttf"), std::runtime_error);
}

TEST(ProbeLabel, CountsAToZThenAA) {
  EXPECT_EQ(probeLabel(0), "A");
  EXPECT_EQ(probeLabel(25), "Z");
  EXPECT_EQ(probeLabel(26), "AA");
  EXPECT_EQ(probeLabel(27), "AB");
  EXPECT_EQ(probeLabel(26 + 26 * 26), "AAA");
}

}  // namespace
}  // namespace tlab::stimuli
