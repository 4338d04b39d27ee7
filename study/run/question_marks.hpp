#pragma once
// The marks of a question as the study shows them: a white and black ring on each point and its
// label outlined in white (TextPainter), on an 8-bit Canvas. The stimulus sets draw boxed labels
// instead (stimuli::LabelPainter); both are MarkPainters of the one StimulusProducer.
#include <vector>

#include "core/image.hpp"
#include "stimuli/sets/mark_painter.hpp"
#include "study/run/canvas.hpp"
#include "study/run/text_painter.hpp"
#include "tasks/question.hpp"

namespace tlab::study {

// A question's points as the marks the stimulus producer draws (targets included: the producer
// leaves out what a participant must not see).
std::vector<stimuli::ProbeMark> probeMarks(const tasks::Question& question);

// `marks` drawn onto an 8-bit copy of `picture`.
Canvas drawOutlinedMarks(const core::Image& picture, const std::vector<stimuli::ProbeMark>& marks, TextPainter& painter);

class OutlinedMarkPainter final : public stimuli::MarkPainter {
 public:
  explicit OutlinedMarkPainter(TextPainter& painter) : painter_(painter) {}
  core::Image drawMarks(const core::Image& picture, const std::vector<stimuli::ProbeMark>& marks) override {
    return drawOutlinedMarks(picture, marks, painter_).toImage();
  }

 private:
  TextPainter& painter_;
};

}  // namespace tlab::study
