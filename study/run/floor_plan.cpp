#include "study/run/floor_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tlab::study {

namespace {
constexpr float kPlanFovyDegrees = 8.0f;  // narrow: close to an orthographic map
}

FloorPlan makeFloorPlan(const render::Scene& scene, int width, int height) {
  const render::BoundingSphere sphere = scene.boundingSphere();
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& o : scene.objects)
    for (const auto& p : o.mesh.positions) lowest = std::min(lowest, double(p.y));
  FloorPlan plan;
  plan.width = width;
  plan.height = height;
  plan.floorY = std::isfinite(lowest) ? lowest : sphere.center.y;
  const float aspect = float(width) / float(height);
  const float halfFov = glm::radians(kPlanFovyDegrees) / 2.0f;
  const float fit = sphere.radius / std::sin(std::min(halfFov, std::atan(std::tan(halfFov) * aspect)));
  plan.camera.target = sphere.center;
  plan.camera.eye = sphere.center + glm::vec3(0.0f, fit, 0.0f);
  plan.camera.up = glm::vec3(0.0f, 0.0f, -1.0f);  // north (−z) at the top of the plan
  plan.camera.fovyDegrees = kPlanFovyDegrees;
  plan.camera.nearPlane = std::max(1e-3f, fit - 1.5f * sphere.radius);
  plan.camera.farPlane = fit + 1.5f * sphere.radius;
  return plan;
}

glm::dvec2 FloorPlan::worldAt(glm::dvec2 pixel) const {
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(camera.projection(float(width) / float(height)) * camera.view()));
  const glm::dvec2 ndc(2.0 * pixel.x / width - 1.0, 1.0 - 2.0 * pixel.y / height);
  glm::dvec4 nearPoint = inverse * glm::dvec4(ndc, -1.0, 1.0), farPoint = inverse * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w, b = glm::dvec3(farPoint) / farPoint.w;
  const double t = (floorY - a.y) / (b.y - a.y);
  const glm::dvec3 hit = a + t * (b - a);
  return {hit.x, hit.z};
}

glm::dvec2 FloorPlan::pixelOf(glm::dvec3 world) const {
  const glm::dvec4 clip = glm::dmat4(camera.projection(float(width) / float(height)) * camera.view()) * glm::dvec4(world, 1.0);
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return {(ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height};
}

}  // namespace tlab::study
