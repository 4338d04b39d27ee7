#pragma once
// LiveView: the scene of an interactive trial rendered with the trial's style from the camera the
// participant steers (CameraNavigator); re-rendered only after the camera moved. Needs the
// window's GL context to be current.
#include <memory>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene.hpp"
#include "study/run/camera_navigator.hpp"
#include "study/run/canvas.hpp"
#include "study/design/session_plan.hpp"

namespace tlab::study {

class LiveView {
 public:
  LiveView(std::shared_ptr<const render::Scene> scene, const StimulusKey& stimulus, Navigation navigation, const render::Camera& start);

  CameraNavigator& navigator() { return navigator_; }
  const CameraNavigator& navigator() const { return navigator_; }
  // The cursor over the picture, in fractions of it ((0, 0) = top left): with the dynamic style in
  // active mode (Elmqvist Sec. V), its lens follows the cursor.
  // Returns whether the picture changes.
  bool pointAt(glm::vec2 fraction);
  // The picture from the navigator's current camera.
  const Canvas& frame();
  // The picture from any camera (the views of an online turntable).
  Canvas frameFrom(const render::Camera& camera);

 private:
  std::shared_ptr<const render::Scene> scene_;
  render::Renderer renderer_;
  render::RenderRequest request_;
  CameraNavigator navigator_;
  std::optional<Canvas> last_;
  std::string lastCamera_;
  bool lens_ = false;         // the style's lens follows the cursor
  float lensRadius_ = 0.2f;
};

}  // namespace tlab::study
