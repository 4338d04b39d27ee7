#include "stimuli/scenes/shape_primitives.hpp"

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/builtin_scenes.hpp"

namespace tlab::stimuli {

namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

std::uint32_t addVertex(render::TriangleMesh& m, glm::vec3 p, glm::vec3 n, glm::vec2 st) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  m.st.push_back(st);
  return std::uint32_t(m.positions.size() - 1);
}

// A ring strip between two circles (y0, r0) → (y1, r1) about the y axis, outward facing.
void appendRevolvedStrip(render::TriangleMesh& m, float y0, float r0, float y1, float r1, int segments) {
  const glm::vec2 profile(r1 - r0, y1 - y0);
  const glm::vec2 outward = glm::normalize(glm::vec2(profile.y, -profile.x));  // (radial, y)
  const std::uint32_t base = std::uint32_t(m.positions.size());
  for (int i = 0; i <= segments; ++i) {
    const float a = kTwoPi * float(i) / float(segments);
    const glm::vec3 dir(std::cos(a), 0.0f, -std::sin(a));
    const glm::vec3 n = glm::normalize(outward.x * dir + glm::vec3(0.0f, outward.y, 0.0f));
    addVertex(m, dir * r0 + glm::vec3(0, y0, 0), n, {float(i) / float(segments), 0.0f});
    addVertex(m, dir * r1 + glm::vec3(0, y1, 0), n, {float(i) / float(segments), 1.0f});
  }
  for (int i = 0; i < segments; ++i) {
    const std::uint32_t a = base + 2 * i, b = a + 1, c = a + 2, d = a + 3;
    m.triangles.push_back({a, c, d});
    m.triangles.push_back({a, d, b});
  }
}

}  // namespace

render::TriangleMesh makeAnnulus(float innerRadius, float outerRadius, int segments) {
  render::TriangleMesh m;
  const std::uint32_t base = 0;
  for (int i = 0; i <= segments; ++i) {
    const float a = kTwoPi * float(i) / float(segments);
    const glm::vec3 dir(std::cos(a), 0.0f, -std::sin(a));
    addVertex(m, dir * innerRadius, {0, 1, 0}, {float(i) / float(segments), 0.0f});
    addVertex(m, dir * outerRadius, {0, 1, 0}, {float(i) / float(segments), 1.0f});
  }
  for (int i = 0; i < segments; ++i) {
    const std::uint32_t a = base + 2 * i, b = a + 1, c = a + 2, d = a + 3;
    m.triangles.push_back({a, b, d});
    m.triangles.push_back({a, d, c});
  }
  return m;
}

render::TriangleMesh makeDisk(float radius, int segments) {
  render::TriangleMesh m;
  const std::uint32_t center = addVertex(m, {0, 0, 0}, {0, 1, 0}, {0.5f, 0.5f});
  for (int i = 0; i <= segments; ++i) {
    const float a = kTwoPi * float(i) / float(segments);
    addVertex(m, {radius * std::cos(a), 0.0f, -radius * std::sin(a)}, {0, 1, 0}, {float(i) / float(segments), 1.0f});
  }
  for (int i = 0; i < segments; ++i) m.triangles.push_back({center, center + 1 + std::uint32_t(i), center + 2 + std::uint32_t(i)});
  return m;
}

render::TriangleMesh makeCone(float radius, float height, int segments) {
  render::TriangleMesh m;
  // The side as a stack of strips up to a tiny tip radius (keeps normals well defined).
  const int rings = 4;
  for (int k = 0; k < rings; ++k) {
    const float f0 = float(k) / rings, f1 = float(k + 1) / rings;
    appendRevolvedStrip(m, f0 * height, radius * (1.0f - f0), f1 * height, std::max(radius * (1.0f - f1), radius * 1e-3f), segments);
  }
  render::TriangleMesh base = makeDisk(radius, segments);
  transformMesh(base, glm::rotate(glm::mat4(1.0f), std::numbers::pi_v<float>, glm::vec3(1, 0, 0)));  // face −y
  appendMesh(m, base);
  return m;
}

render::TriangleMesh makeCylinder(float radius, float height, int segments, bool capped) {
  render::TriangleMesh m;
  appendRevolvedStrip(m, 0.0f, radius, height, radius, segments);
  if (capped) {
    render::TriangleMesh top = makeDisk(radius, segments);
    transformMesh(top, glm::translate(glm::mat4(1.0f), {0, height, 0}));
    render::TriangleMesh bottom = makeDisk(radius, segments);
    transformMesh(bottom, glm::rotate(glm::mat4(1.0f), std::numbers::pi_v<float>, glm::vec3(1, 0, 0)));
    appendMesh(m, top);
    appendMesh(m, bottom);
  }
  return m;
}

render::TriangleMesh makeTorusArc(float R, float r, float from, float to, int majorSegments, int minorSegments) {
  render::TriangleMesh m;
  for (int i = 0; i <= majorSegments; ++i) {
    const float u = from + (to - from) * float(i) / float(majorSegments);
    const glm::vec3 center(R * std::cos(u), R * std::sin(u), 0.0f);
    const glm::vec3 radial(std::cos(u), std::sin(u), 0.0f);
    for (int j = 0; j <= minorSegments; ++j) {
      const float v = kTwoPi * float(j) / float(minorSegments);
      const glm::vec3 n = std::cos(v) * radial + std::sin(v) * glm::vec3(0, 0, 1);
      addVertex(m, center + r * n, n, {float(i) / float(majorSegments), float(j) / float(minorSegments)});
    }
  }
  const int stride = minorSegments + 1;
  for (int i = 0; i < majorSegments; ++i)
    for (int j = 0; j < minorSegments; ++j) {
      const std::uint32_t a = std::uint32_t(i * stride + j), b = a + 1, c = a + std::uint32_t(stride), d = c + 1;
      m.triangles.push_back({a, c, d});
      m.triangles.push_back({a, d, b});
    }
  return m;
}

render::TriangleMesh placed(render::TriangleMesh mesh, glm::vec3 position, float yaw, float pitch, glm::vec3 scale) {
  glm::mat4 t = glm::translate(glm::mat4(1.0f), position);
  t = glm::rotate(t, yaw, glm::vec3(0, 1, 0));
  t = glm::rotate(t, pitch, glm::vec3(1, 0, 0));
  t = glm::scale(t, scale);
  transformMesh(mesh, t);
  return mesh;
}

}  // namespace tlab::stimuli
