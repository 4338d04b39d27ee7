#include "renderer/compose/host_blend.hpp"

#include <algorithm>

#include "core/parallel_shares.hpp"

namespace tlab::render {

namespace {

constexpr std::size_t kRowsPerThreadMin = 16;  // fewer rows a thread cost more to start than they save

// GLSL's unpackUnorm4x8(word).rgb: each byte over 255.
glm::vec3 unpackRgb(std::uint32_t word) {
  return glm::vec3(float(word & 0xFFu) / 255.0f, float((word >> 8) & 0xFFu) / 255.0f, float((word >> 16) & 0xFFu) / 255.0f);
}

// The shaders' main() for the list of `n` fragments from `head`, term by term.
glm::vec4 blendList(const SortedColours& in, std::uint32_t head, std::uint32_t n, float alpha, glm::vec3 background) {
  glm::vec3 c(0.0f);
  float T = 1.0f;  // remaining transmittance
  for (std::uint32_t f = head; f < head + n; ++f) {
    const float a = in.alpha ? std::clamp(in.alpha[f], 0.0f, 1.0f) : alpha;
    const float b = in.beta ? in.beta[f] : 0.0f, g = in.gamma ? in.gamma[f] : 0.0f;
    const float aHat = (1.0f - g) * (a + (1.0f - a) * b);
    const glm::vec3 ci = unpackRgb(in.plane[f]);
    const float weight = T * aHat;  // GLSL's T * aHat * ci: (T·α̂)·c_i
    c += weight * ci;
    T *= 1.0f - aHat;
  }
  return glm::vec4(c + T * background, 1.0f);
}

}  // namespace

void blendOnHost(const SortedColours& in, int x0, int y0, int x1, int y1, float alpha, glm::vec3 background,
                 core::Image& image, unsigned threads) {
  const glm::vec4 outside(background, 1.0f);
  std::fill(image.pixels.begin(), image.pixels.end(), outside);
  x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, in.width), y1 = std::min(y1, in.height);
  if (x1 <= x0 || y1 <= y0) return;
  const std::size_t rows = std::size_t(y1 - y0);
  core::forEachShare(rows, core::sharesFor(rows, kRowsPerThreadMin, threads), [&](std::size_t from, std::size_t to, std::size_t) {
    for (std::size_t r = from; r < to; ++r) {
      const int y = y0 + int(r);
      glm::vec4* const row = &image.pixels[std::size_t(in.height - 1 - y) * std::size_t(image.width)];
      const std::size_t glRow = std::size_t(y) * std::size_t(in.width);
      for (int x = x0; x < x1; ++x) {
        const std::uint32_t n = in.counts[glRow + x];
        if (n > 0) row[x] = blendList(in, in.heads[glRow + x], n, alpha, background);
      }
    }
  });
}

}  // namespace tlab::render
