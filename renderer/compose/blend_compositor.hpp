#pragma once
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

// Front-to-back alpha blending of the sorted lists with one opacity for every fragment
// (compose/blend.comp).
void composeBlend(FrameContext& frame, float alpha);

}  // namespace tlab::render
