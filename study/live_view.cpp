#include "study/live_view.hpp"

#include "renderer/styles/style_params.hpp"

namespace tlab::study {

namespace {

// A walking step of 1/40 of the scene's bounding radius per arrow-key press (Elmqvist's rooms are
// crossed in a few seconds of key repeat).
float stepFor(const render::Scene& scene) { return std::max(1e-3f, scene.boundingSphere().radius / 40.0f); }

}  // namespace

LiveView::LiveView(std::shared_ptr<const render::Scene> scene, const StimulusKey& stimulus, Navigation navigation, const render::Camera& start)
    : scene_(std::move(scene)), renderer_(*scene_), navigator_(navigation, start, stepFor(*scene_)) {
  request_.width = stimulus.width;
  request_.height = stimulus.height;
  request_.style = stimulus.style;
  for (const auto& s : stimulus.renderSettings) render::addSetting(request_.settings, s);
  request_.timePasses = false;
}

const Canvas& LiveView::frame() {
  const std::string camera = navigator_.describe();
  if (!last_ || camera != lastCamera_) {
    request_.camera = navigator_.camera();
    last_.emplace(renderer_.render(request_));
    lastCamera_ = camera;
  }
  return *last_;
}

}  // namespace tlab::study
