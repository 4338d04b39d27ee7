#include "study/run/question_marks.hpp"

#include <algorithm>

namespace tlab::study {

std::vector<stimuli::ProbeMark> probeMarks(const tasks::Question& question) {
  std::vector<stimuli::ProbeMark> marks;
  for (const auto& p : question.points) marks.push_back({p.label, p.role, p.world, p.pixel});
  return marks;
}

Canvas drawOutlinedMarks(const core::Image& picture, const std::vector<stimuli::ProbeMark>& marks, TextPainter& painter) {
  Canvas canvas(picture);
  const float textSize = std::max(12.0f, float(picture.height) / 32.0f);
  for (const auto& p : marks) {
    const double x = p.pixel.x, y = p.pixel.y;
    canvas.strokeCircle(x, y, 4.0, 3.5, {255, 255, 255, 255});
    canvas.strokeCircle(x, y, 4.0, 1.5, {0, 0, 0, 255});
    const int tx = int(x) + 6, ty = int(y) - int(textSize) - 2;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) painter.drawLine(canvas, p.label, tx + dx, ty + dy, textSize, {255, 255, 255, 255});
    painter.drawLine(canvas, p.label, tx, ty, textSize, {0, 0, 0, 255});
  }
  return canvas;
}

}  // namespace tlab::study
