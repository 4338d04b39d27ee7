#pragma once
// Draws probe markers with their letters onto a stimulus image, the way Carnecky et al.'s stimuli
// mark points: a small ring on the exact point and the label in a white box with a dark border
// next to it. Letters are rasterized from a TrueType font (stb_truetype, DejaVu Sans Bold).
#include <memory>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "stimuli/sets/mark_painter.hpp"
#include "stimuli/sets/probe_source.hpp"

namespace tlab::stimuli {

class LabelPainter final : public MarkPainter {
 public:
  // Loads the font; throws std::runtime_error naming the file when it cannot.
  explicit LabelPainter(const std::string& fontPath = defaultFontPath());
  ~LabelPainter();
  LabelPainter(const LabelPainter&) = delete;
  LabelPainter& operator=(const LabelPainter&) = delete;

  static std::string defaultFontPath();

  // Draws every mark; sizes scale with the image (letters about 1/40 of its height).
  void paint(core::Image& image, const std::vector<ProbeMark>& marks) const;
  core::Image drawMarks(const core::Image& picture, const std::vector<ProbeMark>& marks) override;
  // Draws `text` with its top-left corner at (x, y), `pixelHeight` tall.
  void drawText(core::Image& image, double x, double y, const std::string& text, double pixelHeight, glm::vec4 color) const;
  // Width in pixels of `text` at `pixelHeight`.
  double textWidth(const std::string& text, double pixelHeight) const;

 private:
  struct Font;
  std::unique_ptr<Font> font_;
};

}  // namespace tlab::stimuli
