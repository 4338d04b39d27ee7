#pragma once
// StimulusProducer: the one place a stimulus is made, for the stimulus sets (stimuli/sets/
// stimulus_set_renderer) and the study (study/run/stimulus_library): the picture of a scene in a
// style from a camera, the probe marks a participant sees drawn onto it, the PNG bytes and their
// SHA-256 (the name manifests and study records give it). Marks come as ProbeMarks, so tasks/ stay
// out of stimuli/: whoever holds a task's question (app, study) hands over its points. The marks
// are drawn by a MarkPainter the caller chooses — the sets' boxed labels (LabelPainter) and the
// study's outlined labels look different, and each keeps its exact pixels.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "stimuli/sets/mark_painter.hpp"
#include "stimuli/sets/probe_source.hpp"

namespace tlab::stimuli {

// What a stimulus picture is rendered from (the Renderer holds the scene).
struct StimulusView {
  int width = 512, height = 512;
  std::string style;
  std::map<std::string, std::string> settings;
  render::Camera camera;
};

struct ProducedStimulus {
  core::Image image;               // as shown: the picture and its marks
  std::vector<std::uint8_t> png;   // image encoded
  std::string sha256;              // of png
};

// Marks with the role "target" are ground truth (where the answer is), never drawn.
std::vector<ProbeMark> visibleMarks(const std::vector<ProbeMark>& marks);

class StimulusProducer {
 public:
  explicit StimulusProducer(MarkPainter& painter) : painter_(painter) {}
  // The picture without marks; a GL context must be current.
  static core::Image picture(render::Renderer& renderer, const StimulusView& view);
  // The picture with the visible ones of `marks`, encoded and hashed.
  ProducedStimulus produce(const core::Image& picture, const std::vector<ProbeMark>& marks) const;

 private:
  MarkPainter& painter_;
};

}  // namespace tlab::stimuli
