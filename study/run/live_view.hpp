#pragma once
// LiveView: the scene of an interactive trial rendered with the trial's style from the camera the
// participant steers (CameraNavigator); re-rendered only after the camera (or the dynamic lens)
// moved. Needs the window's GL context to be current. The renderer keeps state across frames (the
// dynamic style's group order, seed 004 Alg. 1), so a replay renders the logged frames in order on
// one LiveView, as they were rendered: rendered() tells a front end what each picture was made from.
#include <map>
#include <memory>
#include <optional>
#include <string>

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
  // Replay: the picture from `camera` with the lens at `lens` as pointAt set it (nullopt: the
  // style settings' own lens, as before any pointAt).
  Canvas frameFrom(const render::Camera& camera, std::optional<glm::vec2> lens);

  // What frame() rendered last: its camera, its lens (pointAt's clamped fraction; nullopt before
  // any pointAt or when the lens does not follow the cursor) and how many pictures frame() has
  // rendered so far (0: none).
  struct Rendered {
    render::Camera camera;
    std::optional<glm::vec2> lens;
    int count = 0;
  };
  const Rendered& rendered() const { return rendered_; }

 private:
  std::shared_ptr<const render::Scene> scene_;
  render::Renderer renderer_;
  render::RenderRequest request_;
  CameraNavigator navigator_;
  std::optional<Canvas> last_;
  std::string lastCamera_;
  bool lens_ = false;         // the style's lens follows the cursor
  float lensRadius_ = 0.2f;
  std::map<std::string, std::string> settings_;  // the style's settings before any pointAt
  std::optional<glm::vec2> lensAt_;              // where pointAt put the lens
  Rendered rendered_;
};

}  // namespace tlab::study
