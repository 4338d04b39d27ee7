#include "tasks/view_geometry.hpp"

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace tlab::tasks {

ViewGeometry::ViewGeometry(const render::Camera& camera, int width, int height)
    : width_(width), height_(height), eye_(camera.eye) {
  if (width < 1 || height < 1) throw std::invalid_argument("image size must be at least 1x1");
  forward_ = glm::normalize(glm::dvec3(camera.target) - eye_);
  right_ = glm::normalize(glm::cross(forward_, glm::dvec3(camera.up)));
  const glm::dmat4 view = glm::lookAt(eye_, glm::dvec3(camera.target), glm::dvec3(camera.up));
  const double fovy = glm::radians(double(camera.fovyDegrees));
  const glm::dmat4 projection =
      glm::perspective(fovy, double(width) / double(height), double(camera.nearPlane), double(camera.farPlane));
  viewProjection_ = projection * view;
  inverseViewProjection_ = glm::inverse(viewProjection_);
  tanHalfFovy_ = std::tan(0.5 * fovy);
}

Ray ViewGeometry::rayThrough(glm::dvec2 p) const {
  const glm::dvec2 ndc(2.0 * p.x / width_ - 1.0, 1.0 - 2.0 * p.y / height_);
  const glm::dvec4 far = inverseViewProjection_ * glm::dvec4(ndc, 1.0, 1.0);
  return {eye_, glm::normalize(glm::dvec3(far) / far.w - eye_)};
}

glm::dvec2 ViewGeometry::project(glm::dvec3 world) const {
  const glm::dvec4 clip = viewProjection_ * glm::dvec4(world, 1.0);
  const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
  return {0.5 * (ndc.x + 1.0) * width_, 0.5 * (1.0 - ndc.y) * height_};
}

bool ViewGeometry::inImage(glm::dvec3 world, double margin) const {
  if (depth(world) <= 0.0) return false;
  const glm::dvec2 p = project(world);
  return p.x >= margin && p.y >= margin && p.x <= width_ - margin && p.y <= height_ - margin;
}

double ViewGeometry::pixelFootprint(double depth) const { return 2.0 * depth * tanHalfFovy_ / height_; }

}  // namespace tlab::tasks
