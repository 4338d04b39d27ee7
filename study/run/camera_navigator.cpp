#include "study/run/camera_navigator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace tlab::study {

CameraNavigator::CameraNavigator(Navigation navigation, const render::Camera& start, float step, float degreesPerPixel)
    : navigation_(navigation), camera_(start), step_(step), degreesPerPixel_(degreesPerPixel) {}

namespace {

constexpr float kMaxPitchDegrees = 80.0f;

// The view direction after yaw about `up` and a pitch change, the pitch kept within ±80°.
glm::vec3 turned(glm::vec3 direction, glm::vec3 up, float yawDegrees, float pitchDegrees) {
  const float length = glm::length(direction);
  glm::vec3 d = direction / length;
  const float pitch = glm::degrees(std::asin(std::clamp(glm::dot(d, up), -1.0f, 1.0f)));
  const float newPitch = std::clamp(pitch + pitchDegrees, -kMaxPitchDegrees, kMaxPitchDegrees);
  glm::vec3 horizontal = d - glm::dot(d, up) * up;
  if (glm::length(horizontal) < 1e-6f) horizontal = glm::cross(up, glm::vec3(1, 0, 0));
  horizontal = glm::normalize(horizontal);
  const glm::mat4 yaw = glm::rotate(glm::mat4(1.0f), glm::radians(-yawDegrees), up);
  horizontal = glm::vec3(yaw * glm::vec4(horizontal, 0.0f));
  const float p = glm::radians(newPitch);
  return length * (std::cos(p) * horizontal + std::sin(p) * up);
}

}  // namespace

void CameraNavigator::drag(double dx, double dy) {
  const float yaw = float(dx) * degreesPerPixel_, pitch = float(-dy) * degreesPerPixel_;
  if (navigation_ == Navigation::Orbit) {
    // Elevation of the eye above the target's horizon, kept within ±80° (never over the pole).
    const glm::vec3 up = glm::normalize(camera_.up);
    const glm::vec3 offset = glm::normalize(camera_.eye - camera_.target);
    const float elevation = glm::degrees(std::asin(std::clamp(glm::dot(offset, up), -1.0f, 1.0f)));
    const float wanted = std::clamp(elevation + pitch, -kMaxPitchDegrees, kMaxPitchDegrees);
    camera_ = render::orbit(camera_, -yaw, wanted - elevation);
  } else if (navigation_ == Navigation::Walk) {
    const glm::vec3 up = glm::normalize(camera_.up);
    camera_.target = camera_.eye + turned(camera_.target - camera_.eye, up, yaw, pitch);
  }
}

void CameraNavigator::move(int forward, int turn) {
  const glm::vec3 up = glm::normalize(camera_.up);
  if (navigation_ == Navigation::Walk) {
    if (turn != 0) camera_.target = camera_.eye + turned(camera_.target - camera_.eye, up, 5.0f * float(turn), 0.0f);
    if (forward != 0) {
      glm::vec3 d = camera_.target - camera_.eye;
      glm::vec3 horizontal = d - glm::dot(d, up) * up;
      if (glm::length(horizontal) < 1e-6f) return;
      const glm::vec3 delta = glm::normalize(horizontal) * (step_ * float(forward));
      camera_.eye += delta;
      camera_.target += delta;
    }
  } else if (navigation_ == Navigation::Orbit) {
    if (turn != 0) camera_ = render::orbit(camera_, -5.0f * float(turn), 0.0f);
    if (forward != 0) {
      const glm::vec3 d = camera_.eye - camera_.target;
      const float distance = glm::length(d);
      const float next = std::max(0.1f * step_, distance - step_ * float(forward));
      camera_.eye = camera_.target + d * (next / distance);
    }
  }
}

std::string CameraNavigator::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "eye=%.4f,%.4f,%.4f target=%.4f,%.4f,%.4f", camera_.eye.x, camera_.eye.y, camera_.eye.z,
                camera_.target.x, camera_.target.y, camera_.target.z);
  return text;
}

}  // namespace tlab::study
