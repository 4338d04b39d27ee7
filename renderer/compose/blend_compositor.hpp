#pragma once
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

// Front-to-back alpha blending of the sorted lists with one opacity for every fragment
// (compose/blend.comp).
void composeBlend(FrameContext& frame, float alpha);

class FragmentBuffer;
// Where the host sort wrote the colour plane (FragmentBuffer::colorPlane): its lists blended by
// host code into frame.image over `rect` (compose/host_blend.hpp), timed as the part "compose
// blend on the host". Per fragment, in the plane's order: α, and β and γ after their modifier,
// where given (null: `alpha` for every fragment; β = γ = 0).
void blendColourPlaneOnHost(FrameContext& frame, const FragmentBuffer& buffer, PixelRect rect, float alpha,
                            const float* alphas = nullptr, const float* betas = nullptr, const float* gammas = nullptr);

}  // namespace tlab::render
