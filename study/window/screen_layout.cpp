#include "study/window/screen_layout.hpp"

#include <algorithm>
#include <cmath>

namespace tlab::study {

glm::dvec2 ScreenLayout::toScreen(glm::dvec2 p) const {
  return {stimulus.x + p.x * stimulus.width / double(stimulusWidth), stimulus.y + p.y * stimulus.height / double(stimulusHeight)};
}

glm::dvec2 ScreenLayout::toStimulus(glm::dvec2 s) const {
  return {(s.x - stimulus.x) * stimulusWidth / double(stimulus.width), (s.y - stimulus.y) * stimulusHeight / double(stimulus.height)};
}

int defaultHeaderHeight(int height) { return std::max(48, height / 12); }
int defaultAnswerHeight(int height) { return std::max(96, height / 7); }

ScreenLayout makeScreenLayout(int width, int height, int stimulusWidth, int stimulusHeight, int headerHeightWanted,
                              int answerHeightWanted) {
  ScreenLayout l;
  l.width = width;
  l.height = height;
  l.stimulusWidth = std::max(stimulusWidth, 1);
  l.stimulusHeight = std::max(stimulusHeight, 1);
  const int headerHeight = std::max(defaultHeaderHeight(height), headerHeightWanted);
  const int answerHeight = std::max(defaultAnswerHeight(height), answerHeightWanted), margin = 12;
  l.header = {0, 0, width, headerHeight};
  l.answer = {0, height - answerHeight, width, answerHeight};
  const Rect area{margin, headerHeight + margin, width - 2 * margin, height - headerHeight - answerHeight - 2 * margin};
  // Stimuli are shown at their rendered size or a whole multiple of it (never resampled to an
  // odd scale, which blurs them); only a window too small for the rendered size shrinks them.
  const double fit = std::max(0.01, std::min(area.width / double(l.stimulusWidth), area.height / double(l.stimulusHeight)));
  const double scale = fit >= 1.0 ? std::floor(fit) : fit;
  const int w = int(std::floor(l.stimulusWidth * scale)), h = int(std::floor(l.stimulusHeight * scale));
  l.stimulus = {area.x + (area.width - w) / 2, area.y + (area.height - h) / 2, w, h};
  return l;
}

ScreenLayout makeScreenLayoutWithPlan(int width, int height, int stimulusWidth, int stimulusHeight, int headerHeight,
                                      int answerHeight) {
  constexpr int gap = 12;
  ScreenLayout l = makeScreenLayout(width, height, 2 * std::max(stimulusWidth, 1) + gap, std::max(stimulusHeight, 1), headerHeight,
                                    answerHeight);
  const int half = (l.stimulus.width - gap * l.stimulus.width / l.stimulusWidth) / 2;
  l.plan = Rect{l.stimulus.x + l.stimulus.width - half, l.stimulus.y, half, l.stimulus.height};
  l.stimulus.width = half;
  l.stimulusWidth = std::max(stimulusWidth, 1);
  l.stimulusHeight = std::max(stimulusHeight, 1);
  return l;
}

std::vector<Button> buttonRow(const Rect& band, const std::vector<std::string>& labels, int buttonWidth, int gap) {
  std::vector<Button> out;
  const int n = int(labels.size());
  const int total = n * buttonWidth + std::max(0, n - 1) * gap;
  const int height = std::min(48, band.height - 16);
  int x = band.x + (band.width - total) / 2;
  const int y = band.y + band.height - height - 8;
  for (const auto& label : labels) {
    out.push_back({label, {x, y, buttonWidth, height}});
    x += buttonWidth + gap;
  }
  return out;
}

int hitPoint(const std::vector<glm::dvec2>& points, glm::dvec2 s, double radius) {
  int best = -1;
  double bestDistance = radius;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = glm::length(points[i] - s);
    if (d <= bestDistance) {
      bestDistance = d;
      best = int(i);
    }
  }
  return best;
}

}  // namespace tlab::study
