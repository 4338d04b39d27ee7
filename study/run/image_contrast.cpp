#include "study/run/image_contrast.hpp"

#include <algorithm>
#include <cmath>

namespace tlab::study {

double luminance(const glm::vec4& c) {
  const double a = std::clamp(double(c.a), 0.0, 1.0);
  // Composited over white (the page the participant sees behind a transparent pixel).
  auto channel = [a](float v) { return std::clamp(double(v), 0.0, 1.0) * a + (1.0 - a); };
  return 0.2126 * channel(c.r) + 0.7152 * channel(c.g) + 0.0722 * channel(c.b);
}

double localRmsContrast(const core::Image& image, glm::dvec2 pixel, int radius) {
  const int cx = int(std::floor(pixel.x)), cy = int(std::floor(pixel.y));
  if (cx < 0 || cy < 0 || cx >= image.width || cy >= image.height) return 0.0;
  double sum = 0.0, sumSq = 0.0;
  int n = 0;
  for (int y = std::max(0, cy - radius); y <= std::min(image.height - 1, cy + radius); ++y)
    for (int x = std::max(0, cx - radius); x <= std::min(image.width - 1, cx + radius); ++x) {
      const double l = luminance(image.at(x, y));
      sum += l;
      sumSq += l * l;
      ++n;
    }
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, sumSq / n - mean * mean));
}

}  // namespace tlab::study
