#pragma once
// A frame's lists as host code over the pixels sees them (ops/boundary_conditions.hpp): per pixel
// its fragment count and first sorted record, and the pixels that hold a fragment, in pixel order
// (FragmentBuffer's mapped buffers). No GL here.
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "core/parallel_shares.hpp"

namespace tlab::render {

struct CoveredGrid {
  int width = 0, height = 0;
  const std::uint32_t* counts = nullptr;   // fragments of each pixel
  const std::uint32_t* heads = nullptr;    // each pixel's first fragment in the sorted lists
  const std::uint32_t* covered = nullptr;  // the pixels that hold a fragment, in pixel order
  std::size_t coveredCount = 0;

  bool inside(glm::ivec2 q) const { return q.x >= 0 && q.y >= 0 && q.x < width && q.y < height; }
  std::uint32_t indexAt(glm::ivec2 q) const { return std::uint32_t(q.y * width + q.x); }
  std::uint32_t countAt(glm::ivec2 q) const { return inside(q) ? counts[indexAt(q)] : 0u; }  // none beyond the image
};

// Calls body(pixel, xy, share) for every covered pixel, in pixel order within each of `shares`
// contiguous shares of them (core::forEachShare: one thread a share).
template <class Body>
void forEachCoveredPixel(const CoveredGrid& grid, std::size_t shares, const Body& body) {
  core::forEachShare(grid.coveredCount, shares, [&](std::size_t from, std::size_t to, std::size_t share) {
    if (from == to) return;
    const auto width = std::uint32_t(grid.width);
    std::uint32_t y = grid.covered[from] / width, rowStart = y * width;  // the covered pixels go up: rows counted, not divided
    for (std::size_t k = from; k < to; ++k) {
      const std::uint32_t pixel = grid.covered[k];
      for (; pixel >= rowStart + width; rowStart += width) ++y;
      body(pixel, glm::ivec2(int(pixel - rowStart), int(y)), share);
    }
  });
}

}  // namespace tlab::render
