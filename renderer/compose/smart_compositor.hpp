#pragma once
// Alg. 3 of Carnecky et al. with the profile modifiers of Eqs. 10-11 (compose/smart_compose.comp).
#include "renderer/ops/smart_settings.hpp"
#include "renderer/ops/transparency_fields.hpp"
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

void composeSmart(FrameContext& frame, const TransparencyFields& fields, const SmartSettings& settings);

}  // namespace tlab::render
