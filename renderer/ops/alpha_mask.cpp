#include "renderer/ops/alpha_mask.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <glm/glm.hpp>

namespace tlab::render {

MaskShape parseMaskShape(const std::string& word) {
  if (word == "outline") return MaskShape::Outline;
  if (word == "circle") return MaskShape::Circle;
  if (word == "ellipse") return MaskShape::Ellipse;
  throw std::invalid_argument("mask shape must be outline, circle or ellipse, got '" + word + "'");
}

TargetCoverage TargetCoverage::fromPixels(int width, int height, const std::vector<std::uint32_t>& pixelTarget,
                                          const std::vector<float>& pixelDepth, int size) {
  TargetCoverage c;
  c.size = size;
  c.target.assign(std::size_t(size) * std::size_t(size), 0u);
  c.depth.assign(c.target.size(), 0.0f);
  for (int y = 0; y < height; ++y) {
    const int cy = std::min(size - 1, y * size / height);
    for (int x = 0; x < width; ++x) {
      const std::size_t p = std::size_t(y) * std::size_t(width) + std::size_t(x);
      if (pixelTarget[p] == 0u) continue;
      const std::size_t cell = std::size_t(cy) * std::size_t(size) + std::size_t(std::min(size - 1, x * size / width));
      if (c.target[cell] == 0u || pixelDepth[p] > c.depth[cell]) {
        c.target[cell] = pixelTarget[p];
        c.depth[cell] = pixelDepth[p];
      }
    }
  }
  return c;
}

AlphaMaskSettings AlphaMaskSettings::atImageResolution(AlphaMaskSettings paper, int width, int height) {
  constexpr int kPaperCells = 128;  // seed 004 Sec. V.4
  paper.size = std::max(width, height);
  paper.border = int(std::lround(double(paper.border) * double(paper.size) / kPaperCells));
  return paper;
}

float borderAlpha(int layer, int border, float alpha0) {
  if (layer < 1 || layer > border) return 1.0f;
  return alpha0 + (1.0f - alpha0) * float(layer - 1) / float(border);  // seed 004, Alg. 2 line 8
}

namespace {

// The silhouette at α_T, then the n passes of Alg. 3: a cell still at α = 1 with any of its eight
// neighbours below 1 joins the border with α_B of this pass and the farthest depth among those
// neighbours. Pass i reaches exactly the cells at Chebyshev distance i from the silhouette, so a
// breadth-first search over the 8-neighbour grid gives the same mask in one sweep, O(cells)
// instead of O(n · cells) (the mask may have the image's resolution).
AlphaMask outlineMask(const TargetCoverage& c, const AlphaMaskSettings& s) {
  const int n = c.size;
  AlphaMask m{n, std::vector<float>(c.target.size(), 1.0f), std::vector<float>(c.target.size(), 0.0f)};
  std::vector<int> layer(c.target.size(), -1);
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < c.target.size(); ++i)
    if (c.target[i] != 0u) {
      m.alpha[i] = s.alphaTarget;  // Alg. 2 line 2
      m.depth[i] = c.depth[i];
      layer[i] = 0;
      queue.push_back(i);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t p = queue[head];
    const int next = layer[p] + 1;
    if (next > s.border) continue;
    const int x = int(p % std::size_t(n)), y = int(p / std::size_t(n));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= n || ny >= n) continue;
        const std::size_t q = std::size_t(ny) * std::size_t(n) + std::size_t(nx);
        if (layer[q] == -1) {  // Alg. 3 lines 3-5: joins border layer `next`
          layer[q] = next;
          m.alpha[q] = borderAlpha(next, s.border, s.alpha0);
          m.depth[q] = m.depth[p];
          queue.push_back(q);
        } else if (layer[q] == next) {
          m.depth[q] = std::max(m.depth[q], m.depth[p]);
        }
      }
  }
  return m;
}

// Fig. 2 (a, b): per target a bounding circle or axis-aligned ellipse of its covered cells, in
// units of one cell height (x scaled by the aspect), α_T inside and border layer ⌈d⌉ at
// distance d outside. Overlapping targets: the most transparent value wins.
AlphaMask shapeMask(const TargetCoverage& c, const AlphaMaskSettings& s, float aspect) {
  const int n = c.size;
  struct Extent {
    glm::vec2 lo{1e30f}, hi{-1e30f};
    float depth = 0.0f;
  };
  std::map<std::uint32_t, Extent> extents;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::size_t p = std::size_t(y) * std::size_t(n) + std::size_t(x);
      if (c.target[p] == 0u) continue;
      Extent& e = extents[c.target[p]];
      const glm::vec2 centre((float(x) + 0.5f) * aspect, float(y) + 0.5f);
      e.lo = glm::min(e.lo, centre - glm::vec2(0.5f * aspect, 0.5f));
      e.hi = glm::max(e.hi, centre + glm::vec2(0.5f * aspect, 0.5f));
      e.depth = std::max(e.depth, c.depth[p]);
    }
  AlphaMask m{n, std::vector<float>(c.target.size(), 1.0f), std::vector<float>(c.target.size(), 0.0f)};
  for (const auto& [id, e] : extents) {
    const glm::vec2 centre = 0.5f * (e.lo + e.hi), half = 0.5f * (e.hi - e.lo);
    // The smallest axis-aligned ellipse around a box has semi-axes √2 times its half extents.
    const glm::vec2 axes = s.shape == MaskShape::Circle ? glm::vec2(glm::length(half)) : half * std::sqrt(2.0f);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::vec2 d = glm::vec2((float(x) + 0.5f) * aspect, float(y) + 0.5f) - centre;
        const float r = glm::length(d);
        // The shape's radius along the direction of d.
        const float edge = r > 0.0f ? 1.0f / std::sqrt((d.x / r / axes.x) * (d.x / r / axes.x) +
                                                       (d.y / r / axes.y) * (d.y / r / axes.y))
                                    : 1.0f;
        const float outside = r - edge;
        const float a = outside <= 0.0f ? s.alphaTarget : borderAlpha(int(std::ceil(outside)), s.border, s.alpha0);
        const std::size_t p = std::size_t(y) * std::size_t(n) + std::size_t(x);
        if (a < m.alpha[p] || (a == m.alpha[p] && a < 1.0f && e.depth > m.depth[p])) {
          m.alpha[p] = a;
          m.depth[p] = e.depth;
        }
      }
  }
  return m;
}

}  // namespace

AlphaMask buildAlphaMask(const TargetCoverage& coverage, const AlphaMaskSettings& settings, float aspect) {
  if (coverage.size < 1) throw std::invalid_argument("alpha mask: the mask needs at least 1x1 cells");
  return settings.shape == MaskShape::Outline ? outlineMask(coverage, settings) : shapeMask(coverage, settings, aspect);
}

}  // namespace tlab::render
