#pragma once
// Blending of the bucketed k-buffer (seed 002, Sec. 3 step 3 and Sec. 5.2): each pixel's kept
// fragments in depth order, front to back with float accumulation, after the stylization:
//  Plain:        the shaded colour with constant opacity α (the plain k-buffer, Fig. 9(a));
//  Shading:      mean-curvature shading, colour × 2·tf1(κ), constant α (Fig. 6, Fig. 9(b));
//  Transparency: mean-curvature shading and opacity tf2(|κ|, depth) (Figs. 7-8, Fig. 9(c)).
#include "renderer/kbuffer/bucketed_kbuffer.hpp"
#include "renderer/frame/frame_context.hpp"
#include "renderer/params/transfer_function.hpp"

namespace tlab::render {

enum class CurvatureStylization { Plain, Shading, Transparency };

void composeCurvature(FrameContext& frame, const BucketedKBuffer& buffer, CurvatureStylization stylization,
                      float alpha, const CurvatureShadingFunction& shading, const CurvatureOpacityFunction& opacity);

}  // namespace tlab::render
