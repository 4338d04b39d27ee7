#pragma once
// What a rendered stimulus shows at a point: the local RMS contrast of its luminance (Rec. 709
// weights) in a (2r+1)² window — the standard deviation of luminance, in [0, 0.5]. A silhouette
// or a layer boundary drawn with contrast stands out; a washed-out region does not.
#include <glm/glm.hpp>

#include "core/image.hpp"

namespace tlab::study {

double luminance(const glm::vec4& rgba);
// Window clipped to the image; 0 for a point outside it.
double localRmsContrast(const core::Image& image, glm::dvec2 pixel, int radius = 4);

}  // namespace tlab::study
