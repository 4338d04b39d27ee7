#pragma once
// The gauge figure's frame at a probe (Koenderink, van Doorn & Kappers 1992; Cole et al. 2009):
// w points from the probe to the eye (the line of sight at the probe), u is the image's right made
// perpendicular to w, and v = w × u is the image's up there. A unit normal
//     n = sin σ cos τ · u + sin σ sin τ · v + cos σ · w
// has slant σ (its angle to the line of sight; 0 = facing the viewer) and tilt τ (the direction of
// its image projection, counter-clockwise from the image's right, in [0, 360)). A gauge drawn with
// radius R pixels shows its stick to R sin σ (cos τ, −sin τ) in image pixels (row 0 = top) and its
// disk as an ellipse of axes R and R cos σ, the short one along the tilt.
#include <glm/glm.hpp>

#include "tasks/question.hpp"
#include "tasks/view_geometry.hpp"

namespace tlab::tasks {

struct GaugeFrame {
  glm::dvec3 u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0}, w{0.0, 0.0, 1.0};
};

GaugeFrame gaugeFrame(const ViewGeometry& view, glm::dvec3 point);
// The frame kept with a gauge question (its directions "right", "up", "toward-eye").
GaugeFrame gaugeFrameOf(const Question& q);
void keepGaugeFrame(Question& q, const GaugeFrame& frame);

glm::dvec3 normalFromSlantTilt(const GaugeFrame& f, double slantDegrees, double tiltDegrees);
// (slant, tilt) in degrees of a direction (normalized first).
glm::dvec2 slantTiltOf(const GaugeFrame& f, glm::dvec3 n);

// The angle in degrees between two directions (each normalized first).
double angleDegrees(glm::dvec3 a, glm::dvec3 b);
// The signed difference of two tilts, wrapped to [−180, 180).
double tiltDifference(double a, double b);

}  // namespace tlab::tasks
