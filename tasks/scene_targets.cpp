#include "tasks/scene_targets.hpp"

#include <cctype>
#include <stdexcept>

namespace tlab::tasks {

std::string objectKind(const std::string& name) {
  std::size_t end = name.size();
  while (end > 0 && std::isdigit(static_cast<unsigned char>(name[end - 1]))) --end;
  if (end == name.size()) return name;  // no trailing number
  while (end > 0 && (name[end - 1] == '-' || name[end - 1] == '_' || name[end - 1] == ' ' || name[end - 1] == '#')) --end;
  return name.substr(0, end);
}

std::vector<std::size_t> selectTargets(const render::Scene& scene, const std::string& kind) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto& o = scene.objects[i];
    if (kind.empty() ? render::hasRole(o.roles, render::Role::Target) : objectKind(o.name) == kind) out.push_back(i);
  }
  return out;
}

std::string describeTargets(const std::string& kind) { return kind.empty() ? "targets" : "objects of kind '" + kind + "'"; }

glm::dvec3 surfaceCentroid(const render::TriangleMesh& mesh) {
  glm::dvec3 sum(0.0);
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
    const double w = 0.5 * glm::length(glm::cross(b - a, c - a));
    sum += w * (a + b + c) / 3.0;
    area += w;
  }
  if (area <= 0.0) {
    if (mesh.positions.empty()) throw std::invalid_argument("the centroid of an empty mesh is undefined");
    for (const auto& p : mesh.positions) sum += glm::dvec3(p);
    return sum / double(mesh.positions.size());
  }
  return sum / area;
}

}  // namespace tlab::tasks
