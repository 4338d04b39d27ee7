#include "stimuli/sets/stimulus_producer.hpp"

#include "core/sha256.hpp"

namespace tlab::stimuli {

std::vector<ProbeMark> visibleMarks(const std::vector<ProbeMark>& marks) {
  std::vector<ProbeMark> shown;
  for (const auto& m : marks)
    if (m.role != "target" && m.role != "gauge") shown.push_back(m);  // a gauge is drawn live over the picture
  return shown;
}

core::Image StimulusProducer::picture(render::Renderer& renderer, const StimulusView& view) {
  render::RenderRequest request;
  request.width = view.width;
  request.height = view.height;
  request.style = view.style;
  request.settings = view.settings;
  request.camera = view.camera;
  request.timePasses = false;
  return renderer.render(request);
}

ProducedStimulus StimulusProducer::produce(const core::Image& picture, const std::vector<ProbeMark>& marks) const {
  ProducedStimulus out;
  out.image = painter_.drawMarks(picture, visibleMarks(marks));
  out.png = core::encodePng(out.image);
  out.sha256 = core::sha256Hex(out.png);
  return out;
}

}  // namespace tlab::stimuli
