#pragma once
// CameraNavigator: how a participant moves the camera in an interactive trial (Elmqvist Sec. VI:
// ABSTRACT is explored by orbiting, WALKTHROUGH by walking with mouse and arrow keys, without
// collision). Pure camera arithmetic — no GL, no window — so every motion is unit-tested; the
// window runner feeds it the participant's drags and keys and renders what it returns.
#include <string>

#include "renderer/scene/camera.hpp"
#include "study/design/navigation.hpp"

namespace tlab::study {

class CameraNavigator {
 public:
  // `step` is the walking distance per arrow-key press (world units); `degreesPerPixel` the turn
  // per dragged pixel.
  CameraNavigator(Navigation navigation, const render::Camera& start, float step, float degreesPerPixel = 0.3f);

  Navigation navigation() const { return navigation_; }
  const render::Camera& camera() const { return camera_; }

  // A mouse drag of (dx, dy) pixels: orbit about the target (Orbit) or turn the head (Walk: yaw
  // about the world up, pitch limited to ±80°).
  void drag(double dx, double dy);
  // Arrow keys while walking: `forward` steps along the horizontal view direction (negative:
  // back), `turn` steps of 5° yaw (positive: right). No collision. Ignored when orbiting, except
  // that Up/Down then move the eye toward/away from the target (zoom, never through it).
  void move(int forward, int turn);

  // "eye=x,y,z target=x,y,z" for the event log.
  std::string describe() const;

 private:
  Navigation navigation_;
  render::Camera camera_;
  float step_, degreesPerPixel_;
};

}  // namespace tlab::study
