#pragma once
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

enum class RasterMode { ZBuffer, UnsortedBlend };

// Rasterizes the scene straight into a float colour target and reads it back: with the z-buffer
// (style `opaque`) or with plain alpha blending of opacity `alpha` in submission order (style
// `unsorted`).
void rasterScene(FrameContext& frame, RasterMode mode, float alpha = 1.0f);

}  // namespace tlab::render
