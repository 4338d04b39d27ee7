#pragma once
// Compositing of the IRIS local styles on the illustration buffer
// (compose/illustrative_compose.comp): shading, opacity, window, stripes and silhouettes per
// fragment, front-to-back blending with float accumulation.
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/frame/frame_context.hpp"
#include "renderer/params/illustrative_settings.hpp"

namespace tlab::render {

// Normal variation needs FragmentProperty::NormalZGradient in the buffer, stripes StGradient.
void composeIllustrative(FrameContext& frame, const IllustrativeSettings& settings);

}  // namespace tlab::render
