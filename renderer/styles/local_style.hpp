#pragma once
// Styles whose look is purely local per fragment (IRIS Sec. 5: everything a depth-peeling layer
// shader can compute, plus per-layer Sobel silhouettes). Their settings drive both the
// illustration buffer and the depth-peeling fill (renderer/peel/).
#include "renderer/params/illustrative_settings.hpp"
#include "renderer/styles/style.hpp"

namespace tlab::render {

class LocalStyle : public Style {
 public:
  virtual IllustrativeSettings illustrative(const StyleParams& params) const = 0;
};

// The local shading of `style` (a LocalStyle, or `constant`); throws std::invalid_argument naming
// the style when it is not local (e.g. `smart` needs the whole list).
IllustrativeSettings localShadingOf(const Style& style, const StyleParams& params);

}  // namespace tlab::render
