#include "study/run/live_view.hpp"

#include "renderer/styles/dynamic_style.hpp"
#include "renderer/params/style_params.hpp"

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
  const auto mode = request_.settings.find("mode");
  lens_ = request_.style == "dynamic" && mode != request_.settings.end() && mode->second == "active";
  if (const auto r = request_.settings.find("lens_radius"); lens_ && r != request_.settings.end()) lensRadius_ = std::stof(r->second);
  settings_ = request_.settings;
}

bool LiveView::pointAt(glm::vec2 fraction) {
  if (!lens_) return false;
  lensAt_ = glm::clamp(fraction, glm::vec2(0.0f), glm::vec2(1.0f));
  render::setDynamicLens(request_.settings, *lensAt_, lensRadius_);
  last_.reset();  // the lens moved: render again
  return true;
}

const Canvas& LiveView::frame() {
  const std::string camera = navigator_.describe();
  if (!last_ || camera != lastCamera_) {
    last_.emplace(frameFrom(navigator_.camera()));
    lastCamera_ = camera;
    rendered_ = {navigator_.camera(), lensAt_, rendered_.count + 1};
  }
  return *last_;
}

Canvas LiveView::frameFrom(const render::Camera& camera, std::optional<glm::vec2> lens) {
  if (lens) {
    pointAt(*lens);
  } else {
    request_.settings = settings_;
    lensAt_.reset();
  }
  return frameFrom(camera);
}

Canvas LiveView::frameFrom(const render::Camera& camera) {
  request_.camera = camera;
  return Canvas(renderer_.render(request_));
}

}  // namespace tlab::study
