#pragma once
// The compositing stage of a style file (compose/style_file_compose.comp): the user's
// composite() run once per pixel over its sorted fragments.
#include "renderer/frame/frame_context.hpp"
#include "renderer/params/style_program.hpp"

namespace tlab::render {

// `values`: the per-fragment stage's result (bound as the fragments' `value`), or null.
void composeStyleFile(FrameContext& frame, const StyleProgram& style, const gpu::Buffer* values);

}  // namespace tlab::render
