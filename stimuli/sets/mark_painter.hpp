#pragma once
// How probe marks are drawn onto a stimulus picture (StimulusProducer). Two looks exist and both
// stay pixel for pixel: the stimulus sets' ring and boxed label (LabelPainter) and the study's
// ring and outlined label (study/run/question_marks).
#include <vector>

#include "core/image.hpp"
#include "stimuli/sets/probe_source.hpp"

namespace tlab::stimuli {

class MarkPainter {
 public:
  virtual ~MarkPainter() = default;
  // `picture` with `marks` drawn, as a new image.
  virtual core::Image drawMarks(const core::Image& picture, const std::vector<ProbeMark>& marks) = 0;
};

}  // namespace tlab::stimuli
