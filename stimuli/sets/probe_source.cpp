#include "stimuli/sets/probe_source.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/seeded_random.hpp"

namespace tlab::stimuli {

glm::dvec2 projectToPixel(const render::Camera& camera, int width, int height, const glm::dvec3& world, bool* inFront) {
  const glm::dmat4 m = glm::dmat4(camera.projection(float(width) / float(height))) * glm::dmat4(camera.view());
  const glm::dvec4 clip = m * glm::dvec4(world, 1.0);
  if (inFront) *inFront = clip.w > 0.0;
  const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
  return {(ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height};
}

std::string probeLabel(std::size_t index) {
  std::string reversed;  // bijective base 26: A..Z, AA..AZ, ...
  do {
    reversed.push_back(char('A' + index % 26));
    index = index / 26;
  } while (index-- > 0);
  return std::string(reversed.rbegin(), reversed.rend());
}

std::vector<ProbeQuestion> SurfacePointProbes::probe(const ProbeView& view, const ProbeSetSpec& spec) const {
  struct Triangle {
    glm::dvec3 a, b, c;
  };
  std::vector<Triangle> triangles;
  std::vector<double> cumulativeArea;
  double total = 0.0;
  for (const auto& object : view.scene.objects)
    for (const auto& t : object.mesh.triangles) {
      const Triangle tri{object.mesh.positions[t[0]], object.mesh.positions[t[1]], object.mesh.positions[t[2]]};
      total += 0.5 * glm::length(glm::cross(tri.b - tri.a, tri.c - tri.a));
      triangles.push_back(tri);
      cumulativeArea.push_back(total);
    }
  if (triangles.empty() || !(total > 0.0)) throw std::runtime_error("points: the scene has no surface to mark");
  core::SeededRandom random(spec.seed);
  const double margin = 0.06 * std::min(view.width, view.height);
  const double spacing = 0.08 * std::min(view.width, view.height);
  ProbeQuestion q;
  q.text = "Look at the marked points.";
  q.answerFormat = "free text";
  q.groundTruth = nullptr;
  for (int attempt = 0; attempt < 20000 && int(q.marks.size()) < spec.count; ++attempt) {
    const double pick = double(random.uniform()) * total;
    const std::size_t i = std::size_t(std::lower_bound(cumulativeArea.begin(), cumulativeArea.end(), pick) - cumulativeArea.begin());
    const Triangle& t = triangles[std::min(i, triangles.size() - 1)];
    double u = random.uniform(), v = random.uniform();
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    const glm::dvec3 world = t.a + u * (t.b - t.a) + v * (t.c - t.a);
    bool inFront = false;
    const glm::dvec2 pixel = projectToPixel(view.camera, view.width, view.height, world, &inFront);
    const bool inside = inFront && pixel.x >= margin && pixel.y >= margin && pixel.x <= view.width - margin && pixel.y <= view.height - margin;
    const bool apart = std::all_of(q.marks.begin(), q.marks.end(), [&](const ProbeMark& m) { return glm::distance(m.pixel, pixel) >= spacing; });
    if (inside && apart) q.marks.push_back({probeLabel(q.marks.size()), "probe", world, pixel});
  }
  if (int(q.marks.size()) < spec.count)
    throw std::runtime_error("points: found only " + std::to_string(q.marks.size()) + " of " + std::to_string(spec.count) +
                             " well separated points inside the image");
  return {q};
}

}  // namespace tlab::stimuli
