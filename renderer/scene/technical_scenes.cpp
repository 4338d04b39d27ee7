#include "renderer/scene/technical_scenes.hpp"

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

namespace tlab::render {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

SceneObject makeSolid(std::string name, TriangleMesh mesh, glm::vec3 color, Role roles) {
  SceneObject o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.frontColor = glm::vec4(color, 1.0f);
  o.backColor = glm::vec4(color * 0.55f + glm::vec3(0.1f, 0.15f, 0.3f), 1.0f);
  o.roles = roles;
  return o;
}

int asInt(const std::map<std::string, double>& p, const char* key) { return static_cast<int>(std::lround(p.at(key))); }

Camera lookAt(glm::vec3 eye, glm::vec3 target, float nearPlane, float farPlane) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.nearPlane = nearPlane;
  c.farPlane = farPlane;
  return c;
}

const glm::vec3 kGlass{0.55f, 0.75f, 0.85f};

// Diepstraten colour plate (a): a mug with both boundaries around an opaque box (Sec. 6.2).
Scene mugBoxScene(const std::map<std::string, double>& p) {
  const int segments = asInt(p, "segments");
  Scene s;
  s.name = "mug-box";
  s.objects.push_back(makeSolid("mug", makeMug(1.0f, 0.85f, 2.0f, 0.2f, segments), kGlass, Role::Transparent));
  TriangleMesh box = makeBox({0.3f, 0.7f, 0.3f});
  transformMesh(box, glm::rotate(glm::translate(glm::mat4(1.0f), {0.0f, 0.95f + 0.2f, 0.0f}), 0.5f, glm::vec3(0, 1, 0)));
  s.objects.push_back(makeSolid("box", std::move(box), {0.85f, 0.35f, 0.2f}, Role::Opaque));
  s.camera = lookAt({0.0f, 2.6f, 4.2f}, {0.0f, 0.9f, 0.0f}, 1.0f, 12.0f);
  return s;
}

// Diepstraten colour plate (f): a crank (shaft, two webs, pin) inside a transparent cylinder.
Scene crankCylinderScene(const std::map<std::string, double>& p) {
  const int segments = asInt(p, "segments");
  Scene s;
  s.name = "crank-cylinder";
  s.objects.push_back(makeSolid("cylinder", makeCappedCylinder({-2.0f, 0, 0}, {2.0f, 0, 0}, 1.0f, segments), kGlass,
                                Role::Transparent));
  TriangleMesh crank = makeCappedCylinder({-2.6f, 0, 0}, {-0.45f, 0, 0}, 0.18f, segments / 2);
  appendMesh(crank, makeCappedCylinder({0.45f, 0, 0}, {2.6f, 0, 0}, 0.18f, segments / 2));
  appendMesh(crank, makeCappedCylinder({-0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}, 0.14f, segments / 2));
  for (float x : {-0.5f, 0.5f}) {
    TriangleMesh web = makeBox({0.07f, 0.42f, 0.22f});
    transformMesh(web, glm::translate(glm::mat4(1.0f), {x, 0.25f, 0.0f}));
    appendMesh(crank, web);
  }
  s.objects.push_back(makeSolid("crank", std::move(crank), {0.75f, 0.45f, 0.25f}, Role::Opaque));
  s.camera = lookAt({1.6f, 2.4f, 5.2f}, {0.0f, 0.0f, 0.0f}, 1.0f, 14.0f);
  return s;
}

// Diepstraten colour plates (b, c): several transparent mugs, overlapping in the view, one with
// an opaque box inside.
Scene mugsScene(const std::map<std::string, double>& p) {
  const int segments = asInt(p, "segments"), n = asInt(p, "n");
  Scene s;
  s.name = "mugs";
  for (int i = 0; i < n; ++i) {
    TriangleMesh mug = makeMug(0.8f, 0.68f, 1.6f, 0.16f, segments);
    const float x = (float(i) - 0.5f * float(n - 1)) * 1.25f, z = (i % 2 == 0) ? 0.0f : -1.1f;
    transformMesh(mug, glm::translate(glm::mat4(1.0f), {x, 0.0f, z}));
    const glm::vec3 tint = glm::mix(kGlass, glm::vec3(0.7f, 0.85f, 0.6f), float(i % 3) / 2.0f);
    SceneObject o = makeSolid("mug-" + std::to_string(i), std::move(mug), tint, Role::Transparent);
    o.group = 0;
    s.objects.push_back(std::move(o));
  }
  TriangleMesh box = makeBox({0.25f, 0.55f, 0.25f});
  transformMesh(box, glm::translate(glm::mat4(1.0f), {-0.5f * float(n - 1) * 1.25f, 0.85f, 0.0f}));
  s.objects.push_back(makeSolid("box", std::move(box), {0.85f, 0.35f, 0.2f}, Role::Opaque));
  s.camera = lookAt({0.0f, 2.8f, 5.0f + 0.6f * float(n)}, {0.0f, 0.6f, -0.4f}, 1.0f, 20.0f + float(n));
  return s;
}

}  // namespace

TriangleMesh makeLathe(const std::vector<glm::vec2>& profile, int segments) {
  TriangleMesh m;
  float totalLength = 0.0f;
  for (std::size_t i = 1; i < profile.size(); ++i) totalLength += glm::length(profile[i] - profile[i - 1]);
  float along = 0.0f;
  for (std::size_t i = 1; i < profile.size(); ++i) {
    const glm::vec2 a = profile[i - 1], b = profile[i];
    const glm::vec2 d = b - a;
    const float length = glm::length(d);
    if (length == 0.0f) continue;
    const glm::vec2 n2 = glm::vec2(d.y, -d.x) / length;  // right of the direction: outward
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    for (int k = 0; k <= segments; ++k) {
      const float phi = 2.0f * kPi * float(k) / float(segments);
      const glm::vec3 radial(std::cos(phi), 0.0f, -std::sin(phi));
      for (const auto& [q, t] : {std::pair{a, along}, std::pair{b, along + length}}) {
        m.positions.push_back(radial * q.x + glm::vec3(0.0f, q.y, 0.0f));
        m.normals.push_back(glm::normalize(radial * n2.x + glm::vec3(0.0f, n2.y, 0.0f)));
        m.st.push_back({float(k) / float(segments), t / totalLength});
      }
    }
    along += length;
    for (int k = 0; k < segments; ++k) {
      const std::uint32_t a0 = base + 2 * k, b0 = a0 + 1, a1 = a0 + 2, b1 = a0 + 3;
      for (const std::array<std::uint32_t, 3>& t : {std::array{a0, a1, b1}, std::array{a0, b1, b0}}) {
        const glm::vec3 p0 = m.positions[t[0]], p1 = m.positions[t[1]], p2 = m.positions[t[2]];
        const glm::vec3 geometric = glm::cross(p1 - p0, p2 - p0);
        if (glm::length(geometric) < 1e-12f) continue;  // at the axis
        const glm::vec3 normal = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
        m.triangles.push_back(glm::dot(geometric, normal) >= 0.0f ? t : std::array{t[0], t[2], t[1]});
      }
    }
  }
  return m;
}

TriangleMesh makeMug(float outerRadius, float innerRadius, float height, float bottomThickness, int segments) {
  return makeLathe({{0.0f, 0.0f},
                    {outerRadius, 0.0f},
                    {outerRadius, height},
                    {innerRadius, height},
                    {innerRadius, bottomThickness},
                    {0.0f, bottomThickness}},
                   segments);
}

TriangleMesh makeCappedCylinder(glm::vec3 a, glm::vec3 b, float radius, int segments) {
  const float length = glm::length(b - a);
  TriangleMesh m = makeLathe({{0.0f, 0.0f}, {radius, 0.0f}, {radius, length}, {0.0f, length}}, segments);
  // Rotate +y onto the axis, then move to a.
  const glm::vec3 axis = (b - a) / length, y(0.0f, 1.0f, 0.0f);
  const glm::vec3 r = glm::cross(y, axis);
  glm::mat4 rotation(1.0f);
  if (glm::length(r) > 1e-6f) rotation = glm::rotate(glm::mat4(1.0f), std::acos(glm::clamp(glm::dot(y, axis), -1.0f, 1.0f)), glm::normalize(r));
  else if (glm::dot(y, axis) < 0.0f) rotation = glm::rotate(glm::mat4(1.0f), kPi, glm::vec3(1, 0, 0));
  transformMesh(m, glm::translate(glm::mat4(1.0f), a) * rotation);
  return m;
}

const std::vector<BuiltinSceneSpec>& technicalScenes() {
  static const std::vector<BuiltinSceneSpec> specs = {
      {"mug-box", "a transparent mug with an explicit inner wall around an opaque box (Diepstraten Sec. 6.2)",
       {{"segments", 96, 8, 100000, true, "segments around"}}, mugBoxScene},
      {"crank-cylinder", "an opaque crank inside a transparent closed cylinder (Diepstraten plate f)",
       {{"segments", 64, 8, 100000, true, "segments around"}}, crankCylinderScene},
      {"mugs", "several transparent mugs, one holding an opaque box (Diepstraten plates b, c)",
       {{"n", 3, 1, 16, true, "number of mugs"}, {"segments", 64, 8, 100000, true, "segments around"}}, mugsScene},
  };
  return specs;
}

}  // namespace tlab::render
