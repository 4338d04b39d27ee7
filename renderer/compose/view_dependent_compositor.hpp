#pragma once
// Diepstraten et al. 2002 compositing on the illustration buffer
// (compose/view_dependent_compose.comp) and the black silhouette lines drawn over it
// (ops/silhouette_lines.*).
#include "renderer/ops/view_dependent_alpha.hpp"
#include "renderer/frame/frame_context.hpp"
#include "renderer/params/illustrative_settings.hpp"

namespace tlab::render {

struct ViewDependentSettings {
  bool explicitBoundaries = true;  // Sec. 6.2; false: Sec. 6.1
  float k = 0.5f;                  // fall-off exponent of Eq. 2
  float alphaOpaque = 0.6f;        // weight of the opaque surface behind F1 (Sec. 5)
  float alphaBackground = 0.5f;    // weight of the background behind F1 (Sec. 7)
  // Sec. 7 blends with GL_SRC_ALPHA, GL_DST_ALPHA: c = α·c_T + α_dst·c_dst, whose weights may sum
  // above 1 (a washed-out, brightened interior). Normalised (default): where α + α_dst > 1 both
  // are divided by their sum, so the weights never exceed 1, keep the paper's proportion, and
  // equal the paper's wherever its sum stays ≤ 1.
  bool additiveBlend = false;
  bool lines = true;
  glm::vec3 lineColor{0.0f};
  IllustrativeSettings shading;    // Gooch by default (Sec. 7)
};

void composeViewDependent(FrameContext& frame, const ViewDependentAlpha& alpha, const ViewDependentSettings& settings);

}  // namespace tlab::render
