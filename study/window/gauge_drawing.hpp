#pragma once
// The gauge figure drawn over a stimulus (tasks/gauge_frame.hpp gives the geometry): its disk as an
// ellipse of axes R and R cos σ (the short one along the tilt τ) and its stick from the centre to
// R sin σ (cos τ, −sin τ), in screen pixels with row 0 = top; white under dark so it shows on any
// background. And the inverse: the (slant, tilt) a drag to a screen point sets.
#include <glm/glm.hpp>

#include "study/run/canvas.hpp"

namespace tlab::study {

void drawGauge(Canvas& canvas, glm::dvec2 centre, double radius, double slantDegrees, double tiltDegrees);

// The orientation whose stick ends at `point` (slant at most 85° so the disk stays visible).
glm::dvec2 gaugeToward(glm::dvec2 centre, double radius, glm::dvec2 point);

}  // namespace tlab::study
