#pragma once
// An RGBA float image, row 0 at the top, and its encodings (PNG 8-bit, 16-bit PGM).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace tlab::core {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> pixels;  // width * height, row-major, row 0 = top

  Image() = default;
  Image(int w, int h, glm::vec4 fill = glm::vec4(0.0f)) : width(w), height(h), pixels(std::size_t(w) * h, fill) {}
  glm::vec4& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  const glm::vec4& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

// 8-bit RGBA, row 0 = top; values clamped to [0, 1] and rounded to nearest.
std::vector<std::uint8_t> toRgba8(const Image& image);

// PNG bytes (deterministic: the same image always gives the same bytes).
std::vector<std::uint8_t> encodePng(const Image& image);

// A binary 16-bit PGM (P5, maxval 65535, big-endian samples), row 0 = top.
std::vector<std::uint8_t> encodePgm16(const std::vector<std::uint16_t>& values, int width, int height);

// Writes bytes to `path` through a temporary file and a rename: a failure never leaves a partial
// file behind. Throws std::runtime_error naming the path.
void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes);
// Several output files, all or none: each is written atomically, and if one fails the ones
// already written are removed before the error propagates.
void writeFilesAtomically(const std::vector<std::pair<std::string, std::vector<std::uint8_t>>>& files);

}  // namespace tlab::core
