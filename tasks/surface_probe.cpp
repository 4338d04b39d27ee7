#include "tasks/surface_probe.hpp"

#include <cmath>

#include "tasks/gauge_frame.hpp"

namespace tlab::tasks {

glm::dvec3 shadingNormal(const render::Scene& scene, int object, int triangle, glm::dvec3 point) {
  const auto& mesh = scene.objects.at(std::size_t(object)).mesh;
  const auto& t = mesh.triangles.at(std::size_t(triangle));
  const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
  const glm::dvec3 face = glm::normalize(glm::cross(b - a, c - a));
  if (mesh.normals.size() != mesh.positions.size()) return face;
  // Barycentric coordinates by sub-triangle areas (along the face normal: signed, exact on the plane).
  const double whole = glm::dot(glm::cross(b - a, c - a), face);
  const double wa = glm::dot(glm::cross(c - b, point - b), face) / whole;
  const double wb = glm::dot(glm::cross(a - c, point - c), face) / whole;
  const double wc = 1.0 - wa - wb;
  const glm::dvec3 n = wa * glm::dvec3(mesh.normals[t[0]]) + wb * glm::dvec3(mesh.normals[t[1]]) + wc * glm::dvec3(mesh.normals[t[2]]);
  const double length = glm::length(n);
  return length > 1e-12 ? n / length : face;
}

SurfaceProbe::SurfaceProbe(const render::Scene& scene, const ViewGeometry& view)
    : scene_(scene), view_(view), caster_(scene), mergeDistance_(1e-7 * double(scene.boundingSphere().radius)) {}

std::optional<SurfaceSample> SurfaceProbe::at(glm::dvec2 pixel, int layer) const {
  const Ray ray = view_.rayThrough(pixel);
  const auto hits = caster_.hits(ray, mergeDistance_);
  if (layer < 1 || int(hits.size()) < layer) return std::nullopt;
  const RayHit& h = hits[std::size_t(layer - 1)];
  SurfaceSample s;
  s.point = ray.origin + h.distance * ray.direction;
  s.normal = shadingNormal(scene_, h.object, h.triangle, s.point);
  if (glm::dot(s.normal, view_.eye() - s.point) < 0.0) s.normal = -s.normal;
  s.object = h.object;
  s.layer = layer;
  return s;
}

std::optional<double> SurfaceProbe::continuity(const SurfaceSample& centre, glm::dvec2 pixel, double radiusPixels,
                                               double maxSpreadDegrees) const {
  constexpr double kPi = 3.14159265358979323846;
  const double tanSpread = std::tan(maxSpreadDegrees * kPi / 180.0);
  double spread = 0.0;
  for (int i = 0; i < 8; ++i) {
    const double a = 2.0 * kPi * i / 8.0;
    const auto rim = at(pixel + radiusPixels * glm::dvec2(std::cos(a), std::sin(a)), centre.layer);
    if (!rim || rim->object != centre.object) return std::nullopt;
    const double angle = angleDegrees(rim->normal, centre.normal);
    const glm::dvec3 offset = rim->point - centre.point;
    const double along = glm::length(offset);
    if (angle > maxSpreadDegrees || std::abs(glm::dot(offset, centre.normal)) > tanSpread * along) return std::nullopt;
    spread = std::max(spread, angle);
  }
  return spread;
}

}  // namespace tlab::tasks
