#pragma once
// The front-to-back blending of compose/blend.comp (`constant`) and compose/smart_compose.comp
// (Carnecky Alg. 3) as host code, for where the GL runs on the CPU (issue #29, twenty-eighth
// round): each pixel's colour words, sorted front to back by the host sort (the colour plane:
// buffer/host_sort.hpp), blended with the shaders' float operations in the shaders' order,
//   α̂_i = (1 − γ_i)·(α_i + (1 − α_i)·β_i),  c ← c + (T·α̂_i)·c_i,  T ← T·(1 − α̂_i),
//   and finally c + T·c_background,
// where β_i and γ_i are the modified profiles (Eqs. 10-11, 0 where the field is not read) and
// α̂_i = α for `constant` (β = γ = 0 gives α exactly). So the picture is the shader's, float for
// float (tests compare the two). No GL here: the fragment buffer's mapped counts, heads and plane
// come in, and the fields' values.
#include <cstdint>

#include <glm/glm.hpp>

#include "core/image.hpp"

namespace tlab::render {

struct SortedColours {
  const std::uint32_t* counts = nullptr;  // fragments of each pixel (GL pixel order: row 0 at the bottom)
  const std::uint32_t* heads = nullptr;   // each pixel's first colour word in `plane`
  const std::uint32_t* plane = nullptr;   // RGBA8 words (GLSL's packUnorm4x8), each list front to back
  int width = 0, height = 0;
  // Per fragment, in the plane's order (null: the same for every fragment): α (clamped to [0, 1]
  // here, as smart_compose.comp clamps it), and β and γ after their modifier (null: 0).
  const float* alpha = nullptr;
  const float* beta = nullptr;
  const float* gamma = nullptr;
};

// Blends the pixels of [x0, x1) × [y0, y1) (GL rows) into `image` (row 0 at the top, so GL row y is
// image row height − 1 − y), with opacity `alpha` where `in` holds no α, and `background` behind;
// every other pixel of the image becomes `background` with alpha 1. Rows are shared out among
// `threads` threads.
void blendOnHost(const SortedColours& in, int x0, int y0, int x1, int y1, float alpha, glm::vec3 background,
                 core::Image& image, unsigned threads);

}  // namespace tlab::render
