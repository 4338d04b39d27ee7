#pragma once
// Alg. 3 of Carnecky et al. with the profile modifiers of Eqs. 10-11 (compose/smart_compose.comp).
#include "renderer/ops/smart_settings.hpp"
#include "renderer/ops/transparency_fields.hpp"
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

// Where the GL runs on the CPU and the host sorted the colours (FragmentBuffer::sortsOnHost), the
// blend runs as host code (compose/host_blend.hpp), with Eqs. 10-11 applied by the shader to the
// values that need them (in the fields' scratch buffer).
void composeSmart(FrameContext& frame, TransparencyFields& fields, const SmartSettings& settings);

}  // namespace tlab::render
